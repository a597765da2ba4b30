// A uniform-layer run of the 2D solver, the set-up of §5.2 and §6.2: the layer starts in the
// Bagnold state (5.4)-(5.5) of one mu(I) curve and slope (flat surface, x-uniform), and evolves
// under the solver's curve and slope, which may differ (the decelerating flow changes the slope
// at t = 0; the high-speed flow starts the regularised run from Jop's I_zeta). The x-uniform
// state stays exactly x-uniform on this grid (every column does the same arithmetic), so an
// optional random noise on the initial velocity stands in for the round-off of an adaptive code:
// in an ill-posed region it grows at the grid scale, in a well-posed one it decays.
//
// At `samples` evenly spaced times in [0, t_end] it records the downslope averages u(z) and I(z)
// (figures 3, 5, 8b/d) and the 2D field of I (figures 4, 8a/c). A diverging run is caught and
// recorded with its time, place and quantity; a stop request ends the run at the next sample. In
// both cases the samples taken so far are kept.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "common/mu_curves.hpp"
#include "twod/parameters.hpp"

namespace granbench::cases {

struct LayerRunSpec {
  std::string label;  // e.g. "jop_64x64"
  CurveKind initial_curve = CurveKind::Jop;
  double initial_zeta = 0.0;  // slope of the initial Bagnold state [rad]
  twod::SolverParams params;  // the run's curve, slope, eta cap, ...
  double h0 = 4e-3;           // layer depth [m]
  int nx = 64, nz = 64;
  double Lx = 8e-3, Lz = 8e-3;  // [m]
  double t_end = 0.2;           // [s]
  int samples = 11;             // evenly spaced sample times, both ends included
  double noise = 0.0;           // relative amplitude of the random noise on the initial u
  unsigned seed = 1;            // of the noise
};

struct LayerRunRecord {
  std::string label;
  std::string status = "completed";  // completed, interrupted, diverged, failed
  std::string message;
  double t_reached = 0.0, wall_seconds = 0.0, mass_error = 0.0;
  long steps = 0;
  int nx = 0, nz = 0;
  double Lx = 0.0, Lz = 0.0;
  double initial_I = 0.0;                      // I_zeta of the initial state
  std::vector<double> t;                       // sample times
  std::vector<double> z;                       // cell-centre heights [nz]
  std::vector<std::vector<double>> u_profile;  // [sample][nz]: mean over x of u
  std::vector<std::vector<double>> I_profile;  // [sample][nz]: mean of I over granular cells
  std::vector<std::vector<double>> I_field;    // [sample][nz * nx] (NaN outside the grains)
  std::vector<double> max_speed;               // [sample] max |u| [m/s]
  std::vector<double> illposed_fraction;       // [sample] granular volume with C(I) > 0
};

struct LayerRunProgress {
  const std::atomic<bool>* stop = nullptr;
  std::function<void(const LayerRunRecord&, double t)> report;  // called after each sample
};

LayerRunRecord run_layer(const LayerRunSpec& spec, const LayerRunProgress& progress = {});

}  // namespace granbench::cases

// One chute flow as both models see it: material, curve, slope, depth, periodic domain and the
// initial perturbation (7.2) or a linear eigenmode, and the run length. Defaults are §7's
// rollwave case (zeta = 28.5 deg, h0 = 4 mm, Lx = 8 cm, regularised curve) with a small
// amplitude for linear-regime measurements; the paper's a0 = 0.2 mm is an option.
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include "common/material.hpp"
#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"

namespace granbench {

enum class Seed { Sine, Eigenmode };  // (7.2), or the unstable eigenmode of the model's theory

struct ChuteCase {
  Material material;
  CurveKind curve = CurveKind::Regularised;
  double angle_deg = 28.5;
  double h0 = 4e-3;
  double Lx = 0.08;
  // Amplitude of h [m]. 1 um (2.5e-4 h0) keeps the 2D model's interface cells linear: its
  // surface must move by a small fraction of a cell. At 32 cells per h0 the section 7 growth is
  // 1.0724, 1.0723, 1.0718, 1.0693, 1.0577 1/s at a0 = 1, 2.5, 5, 10, 20 um, and at Lx = 2 cm
  // 0.702, 0.702, 0.699 at 0.4, 1, 2.5 um against 0.474 at 20 um, the former default
  // (docs/twod-validation.md §2, last subsection). The depth-averaged run's window then spans
  // the whole run (its weak nonlinearity had cut it at 1 s with 20 um).
  double a0 = 1e-6;
  Seed seed = Seed::Eigenmode;
  double t_end = 4.0;   // [s]
  double dt_out = 0.0;  // sampling interval [s]; 0: automatic (period/20, at most 0.02 s)

  MuCurve make_curve() const { return MuCurve(curve, material, h0); }
  SteadyState steady() const {
    return steady_state(make_curve(), degrees_to_radians(angle_deg), h0);
  }
};

// What a long run can be told while it goes: progress and a stop request (Ctrl-C).
struct RunControl {
  std::function<void(const std::string& model, double t, double t_end)> progress;
  const std::atomic<bool>* stop = nullptr;
};

// The sampling interval: the automatic value resolves the phase of the wave (|c| dt << Lx) and
// divides t_end into whole samples.
double sampling_interval(const ChuteCase& c, double wave_speed_estimate);

}  // namespace granbench

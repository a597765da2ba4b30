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
  double a0 = 2e-5;  // amplitude of h [m]
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

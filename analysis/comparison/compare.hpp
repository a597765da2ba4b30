// The dual-model comparison: one chute flow run with both models, measured with the same
// analysis code, beside three exact linear theories at the same wavenumber k_hat = 2 pi h0/Lx:
//   exact          the paper's depth-averaged relation (7.11) (shape factor chi = 1);
//   exact_bagnold  the same with the Bagnold shape factor chi = 5/4 (docs/design.md §10);
//   exact_2d       the full 2D linear stability of the Bagnold flow (linear_stability_2d.hpp).
// Each model is measured by the growth rate and phase speed of the seeded mode and of the other
// waves at its wavenumber (matrix pencil fit of h_k(t), surface_measurement.hpp; the seeded one
// is identified by the phase speed of the model's own theory), the paper's estimator (7.12) over
// the same window, and, when the wave has saturated, the nonlinear wave speed (wave_speed.hpp)
// and amplitude.
#pragma once

#include <optional>

#include "analysis/comparison/chute_case.hpp"
#include "analysis/comparison/model_runs.hpp"
#include "analysis/comparison/twod_extrapolation.hpp"
#include "analysis/spectral/measurement.hpp"

namespace granbench {

struct TheoryValue {
  double growth_rate = 0.0;  // [1/s]
  double phase_speed = 0.0;  // [m/s]
};

struct Theories {
  double k_hat = 0.0;
  TheoryValue exact, exact_bagnold, exact_2d;
  double exact_2d_convergence = 0.0;  // relative change of lambda_2d from N to N_check
};
// with_2d = false leaves exact_2d NaN (the 2D eigenproblem costs ~0.7 s per k_hat).
Theories exact_theories(const ChuteCase& c, bool with_2d = true);

struct Comparison {
  ChuteCase chute;
  SteadyState base;
  Theories theory;
  ModelRun depthavg, twod;
  Measurement depthavg_measured, twod_measured;
  // Set with `compare --extrapolate`: the 2D growth rate from this grid and half its cells across
  // the layer (twod_extrapolation.hpp).
  std::optional<TwodExtrapolation> twod_extrapolation;
};

}  // namespace granbench

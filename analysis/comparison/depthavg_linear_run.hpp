// A clean linear-regime measurement with the depth-averaged solver: seed the normal mode (7.10)
// of the (chi-generalised) linearised equations (7.7)-(7.8) at a tiny amplitude, integrate with
// unlimited central reconstruction and tight tolerances, and measure the growth rate and phase
// speed of the seeded mode spectrally (analysis/spectral/surface_measurement.hpp, the seeded
// component identified by the exact phase speed), beside the exact relation (7.11)
// (analysis/theory/dispersion.hpp). One point of `granbench sweep` and of the accuracy tests.
//
// Tolerances are relative to the perturbation (see LinearRunParams). Run length: t_end = max(4 wave
// periods, 0.5 / |Re lambda|), capped at 5 s, unless given; dt_out = min(period/16, t_end/40), so
// the phase unwraps (|c| dt_out < Lx/2).
#pragma once

#include <string>

#include "analysis/spectral/surface_measurement.hpp"
#include "analysis/theory/dispersion.hpp"
#include "depthavg/params.hpp"
#include "depthavg/solver.hpp"

namespace granbench::depthavg {

struct LinearRunParams {
  std::size_t nx = 128;
  // Error control relative to the seeded perturbation, not to the base state: CVODE's
  // rtol = tolerance * amplitude and atol = rtol * h0, so the local error of the perturbation is
  // about `tolerance` of its size.
  double tolerance = 1e-6;
  double amplitude = 1e-4;  // of h, as a fraction of h0; small, because the nonlinear
                            // correction to the growth rate is O(amplitude^2 omega/Re lambda)
  int mode = 1;             // wavelengths in the domain
  double t_end = 0.0;       // 0: automatic
  Reconstruction reconstruction = Reconstruction::Central;
  // Solve in the frame moving at the exact phase speed (rhs.hpp): ~30x fewer steps, and the
  // scheme's advection error no longer enters the measurement. Off by default, so that the
  // measurement tests the lab-frame discretisation.
  bool co_moving = false;
};

struct LinearRunResult {
  double Lx = 0.0;
  DispersionMode exact;         // (7.11) with chi, at k = 2 pi mode / Lx
  SurfaceMeasurement measured;  // NaN numbers and a reason when no clean window
  CvodeStats stats;
  double wall_seconds = 0.0;
  double t_end = 0.0;
  double mass_error = 0.0;
  bool ok = false;  // run completed
  std::string message;
  double growth_relative_error() const {
    return std::fabs(measured.growth_rate - exact.growth_rate) / std::fabs(exact.growth_rate);
  }
  double speed_relative_error() const {
    return std::fabs(measured.phase_speed - exact.phase_speed) / std::fabs(exact.phase_speed);
  }
};

LinearRunResult linear_run(const SteadyState& base, const MuCurve& curve, double chi, double Lx,
                           const LinearRunParams& p);

}  // namespace granbench::depthavg

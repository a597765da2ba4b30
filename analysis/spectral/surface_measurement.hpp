// The one measurement of a run's linear waves, used by `granbench run` (both models), `compare`,
// `sweep` and the depth-averaged linear runs: the Fourier coefficient of mode m,
//
//   h_k(t_n) = sum_j h(x_j, t_n) exp(-i k x_j),   k = 2 pi m / Lx,
//
// fitted over one window by a sum of M = 1..3 damped complex exponentials a_j exp(lambda_j t)
// (matrix pencil, spectral_modes.hpp). For perturbations ~ exp(i k x + lambda t) (7.10) each
// component has growth rate Re lambda_j and phase speed -Im lambda_j / k (docs/design.md §5); its
// amplitude is the height amplitude 2|a_j|/nx [m] at the window start. The seeded component is the
// one whose phase speed is closest to the expected one (from theory) when that is given, else the
// largest at the window start.
//
// Window rules (all options in MeasureOptions):
//  1. Samples: the leading run of samples on the uniform grid t_0 + n dt (within 1e-6 dt). A last
//     sample at t_end off that grid (a run whose t_end is not a multiple of dt_out) and any sample
//     after a gap are left out, with a note.
//  2. Transient: samples before t_0 + transient are skipped (default: the first tenth of the
//     run), so the seed's projection error onto other modes has time to decay.
//  3. Linear regime: the window ends before the mode's amplitude 2|h_k|/nx first exceeds
//     linear_bound * h0 (default 5 % of h0: 0.2 mm for the §7 case), where nonlinear terms
//     (O(amplitude^2) corrections) start to shift the rate. Already above it at the window start:
//     no measurement.
//  4. Model validity: from a start, the window's end advances (stride: 1 % of the usable samples)
//     until the fit (<= 3 resolved exponentials, spectral_modes.hpp) has a relative residual of
//     at most max_residual (default 5e-4) over a window long enough by rule 5, then on while it
//     stays so; the first end where the residual rises above it stops the window: there the data
//     stops being a sum of a few waves (saturation, a stall, a new wave, weak nonlinearity). The
//     starts advance from the transient's end (stride: 5 %), and the longest such window is
//     reported, so that a burst early on (a seed's transient) does not cut the window short when
//     a longer clean one follows it. The default: the §7 2D runs at 32 cells per h0 are described
//     by one wave to 2.6e-4 over 0.29-2 s from the 1 um seed, and the depth-averaged run of
//     `compare` from a 0.02 mm seed departs from its exponential by its weak nonlinearity
//     (1.2177 1/s over 0.2-0.99 s at 5e-4, 1.2134 over 0.2-1.17 s at 1e-3; (7.11): 1.2249).
//  5. Length: the window has at least min_samples samples and spans at least min_efolds e-folds
//     (default 1) or min_periods periods (default 1) of the seeded component.
//  6. Stall: a window that starts later than the transient's end, after |h_k| grew by at least
//     half an e-fold since then, and whose seeded growth rate is below half that earlier mean
//     rate, is a stall (the plateau of a wave that stopped growing, which a travelling wave of
//     constant amplitude fits perfectly). The search stops there; the longest window found before
//     it is reported, and without one there is no measurement.
//  7. Identity: with an expected speed given, the seeded component (the nearest in speed) moves
//     within max_speed_mismatch (default 5 %) of it and carries at least min_seeded_share (1 %)
//     of the largest component's amplitude: below that, with the fit's residual up to 5e-4, a
//     component is the fit's noise. A clean window failing either does not hold the seeded wave
//     and is not taken (40 degrees on the coarse preset, a flow that the theory's slow branch had
//     taken over: a 3-wave fit over 8 ms named a wave at 18.3 m/s, -188 1/s, "the seeded one",
//     26 % off its 14.5 m/s; another over 5 ms one at 14.75 m/s and 657 1/s with 1/2761 of the
//     largest amplitude). The suite's measurements pass unchanged; the validation record's have
//     their seeded wave within 0.2 % of the theory's speed.
// When no window passes, the result has NaN numbers and a `reason`, never a made-up value.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/spectral/spectral_modes.hpp"
#include "common/surface_series.hpp"

namespace granbench {

struct MeasureOptions {
  int mode = 1;                     // wavelengths in the domain
  double seeded_phase_speed = NAN;  // [m/s], expected speed of the seeded mode; NaN: unknown
  double transient = NAN;           // [s] skipped after the first sample; NaN: fraction below
  double transient_fraction = 0.1;  // of the run's duration
  double linear_bound = 0.05;       // of h0; <= 0 or infinite: no bound
  double max_residual = 5e-4;       // relative residual of a clean fit (pencil.target_residual)
  std::size_t min_samples = 16;
  double min_efolds = 1.0;           // the window spans this many e-folds of the seeded mode
  double min_periods = 1.0;          // ... or this many of its periods
  double max_speed_mismatch = 0.05;  // of seeded_phase_speed, for the seeded component (rule 7)
  double min_seeded_share = 0.01;    // of the largest component's amplitude (rule 7)
  PencilOptions pencil;
};

struct WaveMode {
  double growth_rate = NAN;  // Re lambda [1/s]
  double phase_speed = NAN;  // -Im lambda / k [m/s]
  double amplitude = NAN;    // height amplitude at the window start [m]
};

struct SurfaceMeasurement {
  int mode = 1;
  double k = 0.0;                       // [1/m]
  double growth_rate = NAN;             // of the seeded component [1/s]
  double phase_speed = NAN;             // of the seeded component [m/s]
  std::vector<WaveMode> modes;          // every fitted component, largest amplitude first
  std::size_t seeded = 0;               // index of the seeded component in modes
  double t_first = NAN, t_last = NAN;   // window [s]
  std::size_t first = 0, last = 0;      // window, sample indices (inclusive)
  double relative_residual = NAN;       // of the fit over the window
  double log_amplitude_r2 = NAN;        // R^2 of a line through ln|h_k| over the window: below 1
                                        // where waves beat (the former single-exponential test)
  std::vector<double> singular_values;  // of the window's Hankel matrix, over the largest
  std::string reason;                   // why nothing was measured; empty when measured
  std::string note;                     // remarks on the data (samples left out)
  bool found() const { return reason.empty(); }
};

SurfaceMeasurement measure_surface_series(const SurfaceSeries& s, const MeasureOptions& opt = {});

}  // namespace granbench

// Linear growth rate and phase speed of one Fourier mode of a SurfaceSeries h(x, t), for either
// model. With perturbations ~ exp(i k x + lambda t) (7.10), the mode's complex amplitude
//
//   h_k(t) = sum_j h(x_j, t) exp(-i k x_j)  (FFTW, k = 2 pi m / Lx)  ~  A exp(lambda t),
//
// so ln|h_k| is linear in t with slope Re(lambda) (the growth rate, 1/s) and its unwrapped phase
// is linear with slope Im(lambda), giving the phase speed c = -Im(lambda)/k (DESIGN.md §5).
//
// The window where growth is exponential (after transients of other modes, before nonlinear
// saturation) is found automatically: among all windows of at least min_points samples and
// min_fraction of the series whose least-squares fit of ln|h_k| has an RMS residual below max_rms,
// the one spanning the most e-folds |slope| (t_last - t_first) (so a saturated plateau, or a short
// piece of a longer exponential, loses). The fit's R^2 and RMS residual are reported with it.
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

#include "surface_series.hpp"

namespace granbench {

struct LinearFit {
  double slope = 0.0;
  double intercept = 0.0;
  double r2 = 0.0;             // coefficient of determination (meaningless for a zero slope)
  double rms_residual = 0.0;
  std::size_t first = 0, last = 0;  // sample indices, inclusive
  double t_first = 0.0, t_last = 0.0;
};

// Least-squares line through (t[i], y[i]) for i in [first, last].
LinearFit fit_line(std::span<const double> t, std::span<const double> y, std::size_t first,
                   std::size_t last);

struct WindowOptions {
  std::size_t min_points = 8;
  double min_fraction = 0.2;   // of the series' samples
  double max_rms = 1e-3;       // RMS residual of ln|h_k| accepted as linear
};

struct SpectralGrowth {
  int mode = 1;
  double k = 0.0;              // [1/m]
  double growth_rate = 0.0;    // Re(lambda) [1/s]
  double phase_speed = 0.0;    // -Im(lambda)/k [m/s]
  LinearFit amplitude_fit;     // ln|h_k| against t, over the window
  LinearFit phase_fit;         // unwrapped arg(h_k) against t, same window
  bool window_found = false;   // false: no window met max_rms; the best-fitting shortest is used
};

// h_k(t_n) of mode m for every sample.
std::vector<std::complex<double>> mode_amplitudes(const SurfaceSeries& s, int mode);
// Phase unwrapped so successive samples differ by less than pi.
std::vector<double> unwrapped_phase(std::span<const std::complex<double>> z);

SpectralGrowth spectral_growth(const SurfaceSeries& s, int mode = 1,
                               const WindowOptions& opt = {});

}  // namespace granbench

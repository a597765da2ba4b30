// The Fourier coefficient of one mode of a SurfaceSeries h(x, t), for either model, and the
// least-squares line used on its logarithm. With perturbations ~ exp(i k x + lambda t) (7.10),
//
//   h_k(t) = sum_j h(x_j, t) exp(-i k x_j)  (FFTW, k = 2 pi m / Lx)  ~  A exp(lambda t),
//
// so for one wave ln|h_k| is linear in t with slope Re(lambda) and its phase turns at Im(lambda),
// giving c = -Im(lambda)/k (docs/design.md §5). The measurement of growth rates and phase
// speeds, which also separates several waves at one wavenumber, is surface_measurement.hpp; the
// former single-line fit of ln|h_k| over an automatic window (which landed on stalls when waves
// beat) is gone. fit_line remains for (7.12) and the whole-run fit of the comparison.
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

#include "common/surface_series.hpp"

namespace granbench {

struct LinearFit {
  double slope = 0.0;
  double intercept = 0.0;
  double r2 = 0.0;  // coefficient of determination (meaningless for a zero slope)
  double rms_residual = 0.0;
  std::size_t first = 0, last = 0;  // sample indices, inclusive
  double t_first = 0.0, t_last = 0.0;
};

// Least-squares line through (t[i], y[i]) for i in [first, last].
LinearFit fit_line(std::span<const double> t, std::span<const double> y, std::size_t first,
                   std::size_t last);

// h_k(t_n) of mode m for every sample.
std::vector<std::complex<double>> mode_amplitudes(const SurfaceSeries& s, int mode);

}  // namespace granbench

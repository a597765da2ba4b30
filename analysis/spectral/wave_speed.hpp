// Speed of a developed (nonlinear) travelling wave in a SurfaceSeries, by FFT cross-correlation
// of successive snapshots: with h' = h - mean(h),
//
//   C_n(s) = sum_j h'_n(x_j) h'_{n+1}(x_{j+s})   (FFTW: C = IFFT(conj(H_n) H_{n+1})),
//
// the shift s* maximising C_n, refined below one cell by a parabola through the peak and its two
// neighbours, is how far the wave moved: speed = s* dx / (t_{n+1} - t_n). The shift is taken in
// (-Lx/2, Lx/2], so the sampling must satisfy |c| dt < Lx/2 (otherwise the speed aliases).
#pragma once

#include <cstddef>
#include <vector>

#include "common/surface_series.hpp"

namespace granbench {

struct WaveSpeed {
  double speed = 0.0;   // mean over the snapshot pairs [m/s]
  double spread = 0.0;  // standard deviation over the pairs [m/s]
  std::size_t pairs = 0;
  std::vector<double> per_pair;  // speed of each pair, in time order
};

// Shift (in cells, sub-cell) that best maps a onto b on the periodic grid.
double correlation_shift(const std::vector<double>& a, const std::vector<double>& b);
// Uses the pairs with both samples in [t_from, t_to].
WaveSpeed wave_speed(const SurfaceSeries& s, double t_from, double t_to);

}  // namespace granbench

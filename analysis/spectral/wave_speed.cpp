// Wave speed from the phase of the dominant Fourier component; see wave_speed.hpp.
#include "analysis/spectral/wave_speed.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "common/real_fft.hpp"

namespace granbench {

WaveSpeed wave_speed(const SurfaceSeries& s, double t_from, double t_to) {
  const std::size_t nx = s.nx();
  if (nx < 3) throw std::invalid_argument("wave_speed: need at least 3 cells");
  std::vector<std::size_t> samples;
  for (std::size_t n = 0; n < s.nt(); ++n)
    if (s.t[n] >= t_from && s.t[n] <= t_to) samples.push_back(n);
  if (samples.size() < 2)
    throw std::invalid_argument("wave_speed: no snapshot pairs in the window");

  // The modes with a phase: 1 .. (nx - 1)/2 (for even nx the Nyquist mode nx/2 is real).
  const std::size_t top = (nx - 1) / 2;
  RealFFT fft(nx);
  std::vector<double> magnitude(top + 1, 0.0);  // magnitude[0]: the mean depth's, for scale
  for (std::size_t n : samples) {
    const auto H = fft.forward(s.h_at(n));
    for (std::size_t m = 0; m <= top; ++m) magnitude[m] += std::abs(H[m]);
  }
  const auto dominant = std::max_element(magnitude.begin() + 1, magnitude.end());
  // flat to round-off: no phase to follow
  if (!(*dominant > 1e-13 * magnitude[0]))
    throw std::invalid_argument("wave_speed: flat surface, no wave to follow");

  WaveSpeed w;
  const auto m = static_cast<std::size_t>(dominant - magnitude.begin());
  w.mode = static_cast<int>(m);
  w.t_from = s.t[samples.front()];
  w.t_to = s.t[samples.back()];
  const double k = 2.0 * std::numbers::pi * static_cast<double>(m) / s.Lx;
  double turn = 0.0;
  std::complex<double> previous = fft.forward(s.h_at(samples.front()))[m];
  for (std::size_t q = 1; q < samples.size(); ++q) {
    const std::complex<double> current = fft.forward(s.h_at(samples[q]))[m];
    const double d = std::arg(current * std::conj(previous));  // in (-pi, pi]
    turn += d;
    w.per_pair.push_back(-d / (k * (s.t[samples[q]] - s.t[samples[q - 1]])));
    previous = current;
  }
  w.pairs = w.per_pair.size();
  w.speed = -turn / (k * (w.t_to - w.t_from));
  double mean = 0.0;
  for (double v : w.per_pair) mean += v / static_cast<double>(w.pairs);
  for (double v : w.per_pair) w.spread += (v - mean) * (v - mean) / static_cast<double>(w.pairs);
  w.spread = std::sqrt(w.spread);
  return w;
}

}  // namespace granbench

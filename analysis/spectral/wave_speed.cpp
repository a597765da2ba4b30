// Wave speed by FFT cross-correlation of successive snapshots; see wave_speed.hpp.
#include "analysis/spectral/wave_speed.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "common/real_fft.hpp"

namespace granbench {

namespace {

std::vector<double> demeaned(std::span<const double> v) {
  double m = 0.0;
  for (double x : v) m += x;
  m /= static_cast<double>(v.size());
  std::vector<double> out(v.begin(), v.end());
  for (double& x : out) x -= m;
  return out;
}

double shift_with(RealFFT& fft, const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = a.size();
  const auto A = fft.forward(a);
  auto B = fft.forward(b);
  for (std::size_t m = 0; m < B.size(); ++m) B[m] *= std::conj(A[m]);
  const auto C = fft.inverse(B);  // C[s] = n sum_j a_j b_{j+s}
  const auto peak = static_cast<std::size_t>(std::max_element(C.begin(), C.end()) - C.begin());
  const double cm = C[(peak + n - 1) % n], c0 = C[peak], cp = C[(peak + 1) % n];
  const double denom = cm - 2.0 * c0 + cp;
  const double delta = denom < 0.0 ? 0.5 * (cm - cp) / denom : 0.0;  // parabola vertex
  double s = static_cast<double>(peak) + delta;
  if (s > 0.5 * static_cast<double>(n)) s -= static_cast<double>(n);
  return s;
}

}  // namespace

double correlation_shift(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.size() < 3)
    throw std::invalid_argument("correlation_shift: need two signals of equal length >= 3");
  RealFFT fft(a.size());
  return shift_with(fft, demeaned(a), demeaned(b));
}

WaveSpeed wave_speed(const SurfaceSeries& s, double t_from, double t_to) {
  WaveSpeed w;
  if (s.nx() < 3) throw std::invalid_argument("wave_speed: need at least 3 cells");
  RealFFT fft(s.nx());
  const double dx = s.Lx / static_cast<double>(s.nx());
  for (std::size_t n = 0; n + 1 < s.nt(); ++n) {
    if (s.t[n] < t_from || s.t[n + 1] > t_to) continue;
    const double shift = shift_with(fft, demeaned(s.h_at(n)), demeaned(s.h_at(n + 1)));
    w.per_pair.push_back(shift * dx / (s.t[n + 1] - s.t[n]));
  }
  w.pairs = w.per_pair.size();
  if (w.pairs == 0) throw std::invalid_argument("wave_speed: no snapshot pairs in the window");
  for (double v : w.per_pair) w.speed += v / static_cast<double>(w.pairs);
  for (double v : w.per_pair)
    w.spread += (v - w.speed) * (v - w.speed) / static_cast<double>(w.pairs);
  w.spread = std::sqrt(w.spread);
  return w;
}

}  // namespace granbench

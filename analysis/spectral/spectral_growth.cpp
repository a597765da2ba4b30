// Fourier coefficient of one mode and the least-squares line; see spectral_growth.hpp.
#include "analysis/spectral/spectral_growth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "common/real_fft.hpp"

namespace granbench {

LinearFit fit_line(std::span<const double> t, std::span<const double> y, std::size_t first,
                   std::size_t last) {
  if (last <= first || last >= t.size() || t.size() != y.size())
    throw std::invalid_argument("fit_line: need at least two points inside the data");
  const double n = static_cast<double>(last - first + 1);
  double tm = 0.0, ym = 0.0;
  for (std::size_t i = first; i <= last; ++i) {
    tm += t[i] / n;
    ym += y[i] / n;
  }
  double stt = 0.0, sty = 0.0, syy = 0.0;
  for (std::size_t i = first; i <= last; ++i) {
    stt += (t[i] - tm) * (t[i] - tm);
    sty += (t[i] - tm) * (y[i] - ym);
    syy += (y[i] - ym) * (y[i] - ym);
  }
  LinearFit f;
  f.slope = sty / stt;
  f.intercept = ym - f.slope * tm;
  const double sse = std::max(0.0, syy - f.slope * sty);
  f.r2 = syy > 0.0 ? 1.0 - sse / syy : 1.0;
  f.rms_residual = std::sqrt(sse / n);
  f.first = first;
  f.last = last;
  f.t_first = t[first];
  f.t_last = t[last];
  return f;
}

std::vector<std::complex<double>> mode_amplitudes(const SurfaceSeries& s, int mode) {
  if (mode < 1 || static_cast<std::size_t>(mode) > s.nx() / 2)
    throw std::invalid_argument("mode_amplitudes: mode must lie in [1, nx/2]");
  RealFFT fft(s.nx());
  std::vector<std::complex<double>> out(s.nt());
  for (std::size_t n = 0; n < s.nt(); ++n) out[n] = fft.forward(s.h_at(n))[mode];
  return out;
}

}  // namespace granbench

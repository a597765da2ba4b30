// Spectral growth rate and phase speed of a seeded mode; see spectral_growth.hpp.
#include "spectral_growth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "real_fft.hpp"

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

std::vector<double> unwrapped_phase(std::span<const std::complex<double>> z) {
  std::vector<double> p(z.size());
  const double two_pi = 2.0 * std::numbers::pi;
  for (std::size_t i = 0; i < z.size(); ++i) {
    p[i] = std::arg(z[i]);
    if (i > 0) p[i] -= two_pi * std::round((p[i] - p[i - 1]) / two_pi);
  }
  return p;
}

namespace {

// Automatic linear window of y(t): longest span with RMS residual <= max_rms. O(n^2) windows,
// each fitted in O(1) from prefix sums.
LinearFit find_window(std::span<const double> t, std::span<const double> y,
                      const WindowOptions& opt, bool& found) {
  const std::size_t n = t.size();
  const std::size_t min_pts = std::max<std::size_t>(
      {opt.min_points, static_cast<std::size_t>(std::ceil(opt.min_fraction * n)), 3});
  if (n < min_pts) throw std::invalid_argument("spectral_growth: too few samples for a fit");
  // Prefix sums about a shifted origin for conditioning.
  const double t0 = t[0], y0 = y[0];
  std::vector<double> S1(n + 1), St(n + 1), Sy(n + 1), Stt(n + 1), Sty(n + 1), Syy(n + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = t[i] - t0, b = y[i] - y0;
    S1[i + 1] = S1[i] + 1.0;
    St[i + 1] = St[i] + a;
    Sy[i + 1] = Sy[i] + b;
    Stt[i + 1] = Stt[i] + a * a;
    Sty[i + 1] = Sty[i] + a * b;
    Syy[i + 1] = Syy[i] + b * b;
  }
  struct Fit {
    double slope, rms;
  };
  auto fit = [&](std::size_t i, std::size_t j) -> Fit {  // inclusive window [i, j]
    const double m = S1[j + 1] - S1[i], st = St[j + 1] - St[i], sy = Sy[j + 1] - Sy[i];
    const double ctt = (Stt[j + 1] - Stt[i]) - st * st / m;
    const double cty = (Sty[j + 1] - Sty[i]) - st * sy / m;
    const double cyy = (Syy[j + 1] - Syy[i]) - sy * sy / m;
    return {cty / ctt, std::sqrt(std::max(0.0, cyy - cty * cty / ctt) / m)};
  };
  std::size_t bi = 0, bj = min_pts - 1;
  double best_score = -1.0, best_rms = INFINITY;
  found = false;
  for (std::size_t i = 0; i + min_pts <= n; ++i) {
    for (std::size_t j = i + min_pts - 1; j < n; ++j) {
      const Fit f = fit(i, j);
      if (f.rms > opt.max_rms) continue;
      // Number of e-folds the window spans: prefers exponential growth (or decay) over a
      // saturated plateau, and the longer of two windows at the same rate.
      const double score = std::fabs(f.slope) * (t[j] - t[i]) + 1e-12 * (t[j] - t[i]);
      if (score > best_score) {
        found = true;
        best_score = score;
        bi = i;
        bj = j;
      }
    }
  }
  if (!found) {  // best-fitting window of the minimum length
    for (std::size_t i = 0; i + min_pts <= n; ++i) {
      const double r = fit(i, i + min_pts - 1).rms;
      if (r < best_rms) {
        best_rms = r;
        bi = i;
        bj = i + min_pts - 1;
      }
    }
  }
  return fit_line(t, y, bi, bj);
}

}  // namespace

SpectralGrowth spectral_growth(const SurfaceSeries& s, int mode, const WindowOptions& opt) {
  const auto hk = mode_amplitudes(s, mode);
  std::vector<double> ln_amp(hk.size());
  for (std::size_t n = 0; n < hk.size(); ++n) {
    if (!(std::abs(hk[n]) > 0.0))
      throw std::invalid_argument("spectral_growth: the mode has zero amplitude");
    ln_amp[n] = std::log(std::abs(hk[n]));
  }
  const auto phase = unwrapped_phase(hk);
  SpectralGrowth g;
  g.mode = mode;
  g.k = 2.0 * std::numbers::pi * mode / s.Lx;
  g.amplitude_fit = find_window(s.t, ln_amp, opt, g.window_found);
  g.phase_fit = fit_line(s.t, phase, g.amplitude_fit.first, g.amplitude_fit.last);
  g.growth_rate = g.amplitude_fit.slope;        // Re(lambda)
  g.phase_speed = -g.phase_fit.slope / g.k;     // -Im(lambda)/k
  return g;
}

}  // namespace granbench

// The paper's estimator (7.12); see growth_estimator_712.hpp.
#include "analysis/spectral/growth_estimator_712.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granbench {

std::vector<double> excess_height(const SurfaceSeries& s) {
  std::vector<double> a(s.nt());
  for (std::size_t n = 0; n < s.nt(); ++n) {
    const auto h = s.h_at(n);
    a[n] = *std::max_element(h.begin(), h.end()) - s.h0;  // max(h) - h0
  }
  return a;
}

Estimate712 growth_estimate_712(const SurfaceSeries& s, double t_a, double t_b) {
  std::size_t first = s.nt(), last = 0;
  for (std::size_t n = 0; n < s.nt(); ++n)
    if (s.t[n] >= t_a && s.t[n] <= t_b) {
      first = std::min(first, n);
      last = n;
    }
  if (first >= last) throw std::invalid_argument("(7.12): the window holds fewer than two samples");
  const auto a = excess_height(s);
  std::vector<double> ln_a(s.nt(), 0.0);
  for (std::size_t n = first; n <= last; ++n) {
    if (!(a[n] > 0.0)) throw std::invalid_argument("(7.12): max(h) <= h0 inside the window");
    ln_a[n] = std::log(a[n]);
  }
  Estimate712 e;
  // (7.12) averaged over [t_first, t_last]: the mean of d/dt ln(max h - h0).
  e.growth_rate = (ln_a[last] - ln_a[first]) / (s.t[last] - s.t[first]);
  e.fit = fit_line(s.t, ln_a, first, last);
  return e;
}

}  // namespace granbench

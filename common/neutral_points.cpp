// Neutral inertial numbers (roots of C(I), (3.9)) and the neutral curves (4.2)-(4.5).
#include "common/neutral_points.hpp"

#include <algorithm>
#include <cmath>

#include "common/ill_posedness.hpp"
#include "common/root_finding.hpp"

namespace granbench {

std::vector<double> neutral_points(const std::function<double(double)>& mu,
                                   const std::function<double(double)>& dmu_dI, double I_lo,
                                   double I_hi) {
  const std::function<double(double)> c_of_s = [&](double s) {
    const double I = std::exp(s);
    return ill_posedness_C(mu(I), I * dmu_dI(I));  // (3.9)
  };
  constexpr int kSamples = 4000;
  const double s0 = std::log(I_lo), s1 = std::log(I_hi);
  std::vector<double> roots;
  double s_prev = s0, c_prev = c_of_s(s0);
  for (int i = 1; i <= kSamples; ++i) {
    const double s = s0 + (s1 - s0) * i / kSamples;
    const double c = c_of_s(s);
    if (c == 0.0) {
      roots.push_back(std::exp(s));
    } else if (c_prev != 0.0 && (c < 0.0) != (c_prev < 0.0)) {
      roots.push_back(std::exp(brent_root(c_of_s, s_prev, s)));
    }
    s_prev = s;
    c_prev = c;
  }
  return roots;
}

double ill_posedness_C(const MuCurve& curve, double I) {
  return ill_posedness_C(curve.mu(I), I * curve.dmu_dI(I));  // (3.9)
}

WellPosedness analyse_well_posedness(const MuCurve& curve) {
  constexpr double kIlo = 1e-12, kIhi = 1e3;
  WellPosedness w;
  w.neutral = neutral_points([&](double I) { return curve.mu(I); },
                             [&](double I) { return curve.dmu_dI(I); }, kIlo, kIhi);
  // Walk the roots: C changes sign at each one, starting from its sign at the scan floor.
  bool well_posed = ill_posedness_C(curve, kIlo) <= 0.0;
  // Curves with mu -> 0 as I -> 0 stay well posed down to I = 0 ((4.1) and §5.1).
  double lo = well_posed ? (curve.mu_min() == 0.0 ? 0.0 : kIlo) : 0.0;
  for (double r : w.neutral) {
    if (well_posed)
      w.intervals.emplace_back(lo, r);
    else
      lo = r;
    well_posed = !well_posed;
  }
  if (well_posed) w.intervals.emplace_back(lo, kIhi);
  // Name the neutral points as the paper does: the junction of a regularised low-I branch is
  // I1N (the curve is continuous there, C = 0 on the upper branch), otherwise the first root.
  std::vector<double> named = w.neutral;
  if (curve.junction_I() > 0.0) named.insert(named.begin(), curve.junction_I());
  if (!named.empty()) w.I1N = named.front();
  if (named.size() > 1) w.I2N = named[1];
  if (!w.intervals.empty()) w.I_max_wellposed = w.intervals.back().second;
  return w;
}

double neutral_f_plus(double mu) {
  const double s = std::sqrt(std::max(0.0, 4.0 - 2.0 * mu * mu));  // real for mu <= sqrt 2
  return s / (2.0 * mu * mu) + std::log(mu) - 0.5 * std::log(s + 2.0) - 1.0 / (mu * mu);  // (4.4)
}

double neutral_f_minus(double mu) {
  const double s = std::sqrt(std::max(0.0, 4.0 - 2.0 * mu * mu));           // real for mu <= sqrt 2
  return -s / (2.0 * mu * mu) + 0.5 * std::log(s + 2.0) - 1.0 / (mu * mu);  // (4.5)
}

double neutral_slope(double mu, double I, int sign) {
  const double s = std::sqrt(std::max(0.0, 4.0 - 2.0 * mu * mu));  // real for mu <= sqrt 2
  return mu / (I * (16.0 + mu * mu)) * (8.0 + 2.0 * mu * mu + sign * 4.0 * s);  // (4.2)
}

double NeutralCurve::I_of_mu(double mu) const {
  return A * std::exp(sign > 0 ? neutral_f_plus(mu) : neutral_f_minus(mu));  // (4.3)
}

NeutralCurve neutral_curve_through(double I_anchor, double mu_anchor, int sign) {
  const double f = sign > 0 ? neutral_f_plus(mu_anchor) : neutral_f_minus(mu_anchor);
  return NeutralCurve{I_anchor * std::exp(-f), sign};
}

double I_max_from(double I2N, double mu_at_I2N) {
  return std::sqrt(2.0) * I2N * std::exp(-neutral_f_minus(mu_at_I2N) - 0.5);  // §4
}

}  // namespace granbench

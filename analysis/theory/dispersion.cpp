// The temporal dispersion relation of the depth-averaged model with shape factor chi.
//
// Derivation of the chi-generalised relation (chi = 1 gives (7.7)-(7.11)). In the scales (7.13)
// the momentum balance with flux chi h u^2 reads, after subtracting u times (7.3),
//   h u_t + (chi - 1) u (h u)_x + chi h u u_x + F^-2 h h_x = F^-2 Gamma-terms + viscous,
// and about (h, u) = (1, 1) it linearises to
//   F^2 (u_t + (2chi - 1) u_x + (chi - 1) h_x) + h_x = Gamma (3/2 h - u) + F^2/R u_xx.
// The friction term: mu evaluated at I ~ u h^{-3/2} gives -Gamma (u - 3/2 h) with
// Gamma = I_zeta mu'(I_zeta). Substituting exp(i k x + lambda t) and eliminating u with (7.7)
// (u = -(lambda + i k) h/(i k)) gives the quadratic in dispersion.hpp.
//
// Neutral waves (Re lambda = 0, lambda = -i omega, v = omega/k): the real part gives
// F^2 v^2 - 2 chi F^2 v - (1 - chi F^2) = 0, so v = chi + sqrt(chi^2 F^2 + 1 - chi F^2)/F;
// the imaginary part gives v = (5/2 Gamma + F^2 k^2/R)/(Gamma + F^2 k^2/R), hence the cutoff
// k_c^2 = R Gamma (5/2 - v)/(F^2 (v - 1)), real and positive exactly when F^2 (25/4 - 4 chi) > 1.
#include "analysis/theory/dispersion.hpp"

#include <cmath>
#include <functional>
#include <numbers>

#include "common/root_finding.hpp"

namespace granbench {

using cplx = std::complex<double>;
constexpr cplx kI{0.0, 1.0};

DispersionParams DispersionParams::from(const SteadyState& s, double chi) {
  return DispersionParams{s.Fr, s.R, s.Gamma, chi};
}

namespace {
struct Quadratic {
  cplx a, b, c;
};
Quadratic coefficients(const DispersionParams& p, double k) {
  const double F2 = p.F * p.F;
  return {F2, 2.0 * kI * p.chi * F2 * k + p.Gamma + F2 * k * k / p.R,
          (1.0 - p.chi * F2) * k * k + kI * (2.5 * p.Gamma * k + F2 * k * k * k / p.R)};
}
}  // namespace

std::complex<double> dispersion_polynomial(const DispersionParams& p, double k, cplx lambda) {
  const auto q = coefficients(p, k);
  return (q.a * lambda + q.b) * lambda + q.c;
}

std::complex<double> paper_polynomial_7_11(const DispersionParams& p, double k, cplx lambda) {
  const double R = p.R, F2 = p.F * p.F;
  return -kI * R * lambda * lambda + (2.0 * R * k - kI * k * k - kI * R * p.Gamma / F2) * lambda +
         k * k * k + (kI * R - kI * R / F2) * k * k + 5.0 * R * p.Gamma / (2.0 * F2) * k;  // (7.11)
}

DispersionRoots dispersion_roots(const DispersionParams& p, double k) {
  const auto q = coefficients(p, k);
  const cplx disc = std::sqrt(q.b * q.b - 4.0 * q.a * q.c);
  // Cancellation-free pair: one root from the larger-modulus combination, the other by Vieta.
  const cplx big = -0.5 * (q.b + (std::real(std::conj(q.b) * disc) >= 0.0 ? disc : -disc));
  cplx r1 = big / q.a;
  cplx r2 = std::abs(big) > 0.0 ? q.c / big : cplx{0.0, 0.0};
  if (std::real(r2) > std::real(r1)) std::swap(r1, r2);
  return {r1, r2};
}

double critical_froude(double chi) {
  return 2.0 / std::sqrt(25.0 - 16.0 * chi);
}

double cutoff_k_hat_closed_form_chi1(const DispersionParams& p) {
  const double F = p.F;
  return std::sqrt(p.R * p.Gamma * (3.0 * F - 2.0) / (2.0 * F * F));
}

double cutoff_k_hat_closed_form(const DispersionParams& p) {
  const double F = p.F, chi = p.chi;
  const double v = chi + std::sqrt(chi * chi * F * F + 1.0 - chi * F * F) / F;
  return std::sqrt(p.R * p.Gamma * (2.5 - v) / (F * F * (v - 1.0)));
}

std::optional<double> cutoff_k_hat(const DispersionParams& p) {
  if (p.F <= critical_froude(p.chi)) return std::nullopt;
  const std::function<double(double)> growth = [&](double s) {
    return std::real(dispersion_roots(p, std::exp(s)).unstable);
  };
  // Unstable to long waves: Re(lambda) > 0 at small k, < 0 at large k (viscous damping ~ k^2).
  double s_lo = std::log(1e-6), s_hi = std::log(1e-3);
  while (growth(s_hi) > 0.0) {
    s_lo = s_hi;
    s_hi += 1.0;
    if (s_hi > std::log(1e8)) return std::nullopt;
  }
  return std::exp(brent_root(growth, s_lo, s_hi, 1e-14));
}

DispersionMode dispersion_mode(const SteadyState& s, double chi, double Lx) {
  DispersionMode m;
  m.Lx = Lx;
  m.k_hat = 2.0 * std::numbers::pi * s.h0 / Lx;  // (7.13b)
  m.lambda_hat = dispersion_roots(DispersionParams::from(s, chi), m.k_hat).unstable;
  const double scale = s.u_mean / s.h0;  // (7.13a): lambda = lambda_hat u0/h0
  const double k = 2.0 * std::numbers::pi / Lx;
  m.growth_rate = std::real(m.lambda_hat) * scale;
  m.phase_speed = -std::imag(m.lambda_hat) * scale / k;
  return m;
}

double Lx_from_k_hat(const SteadyState& s, double k_hat) {
  return 2.0 * std::numbers::pi * s.h0 / k_hat;
}

}  // namespace granbench

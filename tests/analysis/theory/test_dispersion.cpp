// The temporal dispersion relation: roots of (7.11), its chi-generalised form, a direct eigen-solve
// of (7.7)-(7.8), the long-wave threshold and the cutoff against closed forms.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "analysis/theory/dispersion.hpp"

using namespace granbench;
using cplx = std::complex<double>;

namespace {
SteadyState section7_state() {
  return steady_state(MuCurve(CurveKind::Regularised, Material{}), degrees_to_radians(28.5), 4e-3);
}

// (7.7)-(7.8) with shape factor chi as lambda v = M v for v = (h, u).
Eigen::Matrix2cd linear_operator(const DispersionParams& p, double k) {
  const cplx ik{0.0, k};
  const double F2 = p.F * p.F;
  Eigen::Matrix2cd M;
  M(0, 0) = -ik;  // (7.7)
  M(0, 1) = -ik;
  M(1, 0) = (-F2 * (p.chi - 1.0) * ik - ik + 1.5 * p.Gamma) / F2;  // (7.8)
  M(1, 1) = (-F2 * (2.0 * p.chi - 1.0) * ik - p.Gamma - F2 * k * k / p.R) / F2;
  return M;
}
}  // namespace

TEST(Dispersion, RootsSatisfyThePapersPolynomial711) {
  const DispersionParams p = DispersionParams::from(section7_state());
  for (double k : {0.01, 0.1, 0.3, 1.0, 3.0}) {
    const auto r = dispersion_roots(p, k);
    for (cplx lam : {r.unstable, r.other}) {
      const double scale = std::abs(p.R * lam * lam) + std::pow(k, 3) + p.R * k * k + p.R * k;
      EXPECT_LT(std::abs(paper_polynomial_7_11(p, k, lam)) / scale, 1e-14) << "k = " << k;
      EXPECT_LT(std::abs(dispersion_polynomial(p, k, lam)) / scale, 1e-14);
    }
    EXPECT_GE(r.unstable.real(), r.other.real());
  }
}

TEST(Dispersion, RootsAgreeWithDirectEigenSolveForAnyChi) {
  const SteadyState s = section7_state();
  for (double chi : {1.0, 1.25}) {
    const DispersionParams p = DispersionParams::from(s, chi);
    for (double k : {0.05, 0.3, 1.2}) {
      Eigen::ComplexEigenSolver<Eigen::Matrix2cd> es(linear_operator(p, k));
      auto ev = es.eigenvalues();
      if (ev(1).real() > ev(0).real()) std::swap(ev(0), ev(1));
      const auto r = dispersion_roots(p, k);
      EXPECT_NEAR(std::abs(ev(0) - r.unstable) / std::abs(r.unstable), 0.0, 1e-12);
      EXPECT_NEAR(std::abs(ev(1) - r.other) / std::abs(r.other), 0.0, 1e-12);
    }
  }
}

TEST(Dispersion, LongWaveGrowthChangesSignAtCriticalFroude) {
  // F_c = 2/sqrt(25 - 16 chi): 2/3 for chi = 1 (Gray & Edwards 2014), 2/sqrt(5) for chi = 5/4.
  EXPECT_NEAR(critical_froude(1.0), 2.0 / 3.0, 1e-15);
  for (double chi : {1.0, 1.1, 1.25}) {
    const double Fc = critical_froude(chi);
    for (double factor : {0.99, 1.01}) {
      const DispersionParams p{Fc * factor, 50.0, 0.05, chi};
      const double growth = dispersion_roots(p, 1e-3).unstable.real();
      if (factor < 1.0)
        EXPECT_LT(growth, 0.0) << "chi " << chi;
      else
        EXPECT_GT(growth, 0.0) << "chi " << chi;
    }
  }
}

TEST(Dispersion, CutoffMatchesClosedForms) {
  const SteadyState s = section7_state();
  const DispersionParams p1 = DispersionParams::from(s, 1.0);
  const auto kc1 = cutoff_k_hat(p1);
  ASSERT_TRUE(kc1.has_value());
  EXPECT_NEAR(*kc1 / cutoff_k_hat_closed_form_chi1(p1), 1.0, 1e-10);
  EXPECT_NEAR(cutoff_k_hat_closed_form(p1) / cutoff_k_hat_closed_form_chi1(p1), 1.0, 1e-12);
  EXPECT_NEAR(dispersion_roots(p1, *kc1).unstable.real(), 0.0, 1e-12);
  const DispersionParams p54 = DispersionParams::from(s, 1.25);
  const auto kc54 = cutoff_k_hat(p54);
  ASSERT_TRUE(kc54.has_value());
  EXPECT_NEAR(*kc54 / cutoff_k_hat_closed_form(p54), 1.0, 1e-10);
  // Below the critical Froude number nothing grows: no cutoff.
  EXPECT_FALSE(cutoff_k_hat(DispersionParams{0.5, 50.0, 0.05, 1.0}).has_value());
}

TEST(Dispersion, LongWavesTravelAtTheKinematicSpeed) {
  // k -> 0: lambda_hat -> -i (5/2) k, the kinematic wave speed 5/2 u0 of flux ~ h^{5/2}.
  const DispersionParams p = DispersionParams::from(section7_state());
  // The O(k^2) correction to the speed has a coefficient ~ F^4/Gamma^2 ~ 1e6 here, so go small.
  const double k = 1e-7;
  EXPECT_NEAR(-dispersion_roots(p, k).unstable.imag() / k, 2.5, 1e-6);
}

TEST(Dispersion, Section7ModeMatchesTheDesignNumbers) {
  // docs/design.md §10: chi = 1 gives about 0.84 m/s and 1.2 1/s, chi = 5/4 about 1.22 m/s, 0.2
  // 1/s.
  const SteadyState s = section7_state();
  const auto m1 = dispersion_mode(s, 1.0, 0.08);
  EXPECT_NEAR(m1.phase_speed, 0.84, 0.01);
  EXPECT_NEAR(m1.growth_rate, 1.2, 0.05);
  const auto m54 = dispersion_mode(s, 1.25, 0.08);
  EXPECT_NEAR(m54.phase_speed, 1.22, 0.01);
  EXPECT_NEAR(m54.growth_rate, 0.2, 0.01);
  EXPECT_NEAR(m1.k_hat, 2.0 * M_PI * 4e-3 / 0.08, 1e-15);
}

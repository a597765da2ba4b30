// Physics limits of the 2D linear stability of steady uniform flow (docs/linear-theory.md):
// the kinematic wave speed as k -> 0, the derived long-wave growth coefficient and threshold, the
// classical falling-film threshold for a Newtonian layer, the cutoff, the §7 values, the slow
// second branch, and the ill-posedness signature of the Jop curve at 28.5 deg.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "analysis/linear2d/ill_posedness.hpp"
#include "analysis/linear2d/linear_stability_2d.hpp"

using namespace granbench;
using namespace granbench::linear2d;

namespace {

LinearBaseState bagnold(double zeta_deg, double h0) {
  const MuCurve c(CurveKind::Regularised, Material{}, h0);
  return mu_i_base_state(steady_state(c, degrees_to_radians(zeta_deg), h0), c);
}

// Root of f on [lo, hi] by bisection (f changes sign).
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  double flo = f(lo);
  for (int it = 0; it < 30; ++it) {
    const double mid = 0.5 * (lo + hi), fm = f(mid);
    if ((fm > 0) == (flo > 0)) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST(Linear2DPhysics, LongWavesTravelAtTheKinematicSpeed) {
  const LinearBaseState b = bagnold(28.5, 4e-3);
  // The approach is slow for this flow: the long-wave expansion needs k_hat << Gamma/F^2 ~ 4e-3
  // (phase speed 1.75 u_bar_0 at k_hat = 0.31, 2.33 at 1e-3). The deficit falls like k^2.
  double previous = 0.0;
  for (double k : {1e-3, 1e-4, 1e-5}) {
    const auto l = surface_mode_eigenvalue(b, k, 24);
    const double deficit = 2.5 - (-l.imag() / k);  // dq/dh = (5/2) u_bar_0 for q ~ h^{5/2}
    EXPECT_GT(deficit, 0.0);
    if (previous > 0.0) {
      EXPECT_LT(deficit, previous / 30.0) << k;  // observed 54, 100
    }
    previous = deficit;
  }
  EXPECT_LT(previous, 1e-4);
}

TEST(Linear2DPhysics, LongWaveGrowthMatchesTheDerivedCoefficient) {
  // Re(lambda_hat)/k_hat^2 -> c2 = (5/(2 Gamma)) ((5/8) F^2 - 2/5 + (3/5) mu q), for several
  // depths (F) and angles; the remainder is
  // below 2e-3 relative at k_hat = 1e-5.
  for (double zeta : {25.0, 28.5}) {
    for (double h0 : {1e-3, 2e-3, 4e-3}) {
      const LinearBaseState b = bagnold(zeta, h0);
      const double k = 1e-5;  // well below Gamma/F^2 for all these flows
      const double c2 = long_wave_growth_coefficient(b);
      const auto l = surface_mode_eigenvalue(b, k, 24);
      EXPECT_NEAR(l.real() / (k * k), c2, 2e-3 * std::abs(c2) + 1e-3) << zeta << " " << h0;
    }
  }
}

TEST(Linear2DPhysics, LongWaveThresholdFromDepthScan) {
  // At fixed angle F grows linearly with h0 (7.1); bisect on h0 for the sign change of the
  // long-wave growth rate and compare F there with F_c = sqrt((8/25)(2 - 3 mu q)).
  for (double zeta : {24.0, 28.5}) {
    const double k = 1e-3;
    auto growth = [&](double h0) {
      return surface_mode_eigenvalue(bagnold(zeta, h0), k, 16).real();
    };
    const double h_c = bisect(growth, 1e-4, 2e-2);
    const LinearBaseState b = bagnold(zeta, h_c);
    EXPECT_NEAR(b.F, critical_froude_2d(b.mu, b.Gamma), 1e-4) << zeta;
  }
  // The §7 case: neither 2/3 (depth-averaged, chi = 1) nor 2/sqrt(5) (chi = 5/4).
  const LinearBaseState b = bagnold(28.5, 4e-3);
  EXPECT_NEAR(critical_froude_2d(b.mu, b.Gamma), 0.6076, 5e-4);
}

TEST(Linear2DPhysics, CutoffIsWhereTheSurfaceModeStopsGrowing) {
  // The section 7 case: traced to it afresh from the long-wave limit (surface_mode_eigenvalue's
  // own path, its eigenvalue from the spectrum), the surface mode grows just below the cutoff
  // and decays just above it; the growth changes by ~2e-8 (scaled) over these 1e-6 in k_hat,
  // where the root is found to 1e-10.
  const LinearBaseState b = bagnold(28.5, 4e-3);
  const auto kc = surface_mode_cutoff_k_hat(b, 32);
  ASSERT_TRUE(kc.has_value());
  EXPECT_GT(surface_mode_eigenvalue(b, *kc * (1.0 - 1e-6), 32).real(), 0.0);
  EXPECT_LT(surface_mode_eigenvalue(b, *kc * (1.0 + 1e-6), 32).real(), 0.0);
  // Below the long-wave threshold (a thin layer at 24 degrees) nothing grows, so no cutoff.
  const LinearBaseState thin = bagnold(24.0, 1e-4);
  ASSERT_LT(thin.F, critical_froude_2d(thin.mu, thin.Gamma));
  EXPECT_FALSE(surface_mode_cutoff_k_hat(thin, 32).has_value());
}

TEST(Linear2DPhysics, NewtonianFilmReproducesBenjaminYihThreshold) {
  // Re_c = (5/6) cot(zeta) with Re = u_bar h/nu (Benjamin 1957, Yih 1963); long-wave speed 3 u_bar.
  for (double zeta_deg : {5.0, 20.0, 45.0}) {
    const double zeta = degrees_to_radians(zeta_deg);
    const double k = 1e-2;
    ContinuationOptions path;
    path.N = 12;  // the Nusselt profile is a quadratic: few points resolve it
    auto growth = [&](double F) {
      return surface_mode_eigenvalue(newtonian_film_base_state(F, zeta), k, 12, VerticalMap::Linear,
                                     path)
          .real();
    };
    const double F_c = bisect(growth, 0.2, 1.0);
    const double Re_c = newtonian_film_reynolds(newtonian_film_base_state(F_c, zeta));
    EXPECT_NEAR(Re_c / (5.0 / 6.0 / std::tan(zeta)), 1.0, 1e-3) << zeta_deg;
    const auto l =
        surface_mode_eigenvalue(newtonian_film_base_state(F_c, zeta), k, 20, VerticalMap::Linear);
    EXPECT_NEAR(-l.imag() / k, 3.0, 1e-3);
  }
}

TEST(Linear2DPhysics, Section7CaseAtEightCentimetres) {
  // Regression against our converged value (N = 64: 1.089143 1/s, 1.138015 m/s); the brief's
  // independent Chebyshev solution (1.09 1/s, 1.14 m/s) is the sanity band.
  const MuCurve c(CurveKind::Regularised, Material{}, 4e-3);
  const SteadyState s = steady_state(c, degrees_to_radians(28.5), 4e-3);
  const Linear2DResult r = linear_stability_2d(s, c, 0.08);
  EXPECT_NEAR(r.surface.growth_rate, 1.089143, 1e-5);
  EXPECT_NEAR(r.surface.phase_speed, 1.138015, 1e-5);
  EXPECT_LT(r.surface.relative_difference, 1e-8);
  EXPECT_NEAR(r.surface.growth_rate, 1.09, 0.05);
  EXPECT_NEAR(r.surface.phase_speed, 1.14, 0.02);
  ASSERT_EQ(r.unstable.size(), 1u);  // only the surface mode grows at 8 cm
  EXPECT_TRUE(r.unstable[0].surface);
}

TEST(Linear2DPhysics, SlowSecondBranchIsUnstableNearTwoCentimetres) {
  // A second, slow mode (phase speed ~0.32 m/s, below the surface velocity 1.085 m/s) grows at
  // Lx = 2 cm faster than the surface mode; it is converged in N, so it is a mode of the linear
  // mu(I) problem, not a resolution artefact.
  const MuCurve c(CurveKind::Regularised, Material{}, 4e-3);
  const SteadyState s = steady_state(c, degrees_to_radians(28.5), 4e-3);
  const Linear2DResult r = linear_stability_2d(s, c, 0.02);
  ASSERT_EQ(r.unstable.size(), 2u);
  const Linear2DMode& slow = r.unstable[0];
  EXPECT_FALSE(slow.surface);
  EXPECT_NEAR(slow.growth_rate, 5.8165, 2e-3);
  EXPECT_NEAR(slow.phase_speed, 0.3195, 1e-3);
  EXPECT_LT(slow.relative_difference, 1e-6);
  EXPECT_TRUE(r.unstable[1].surface);
  EXPECT_NEAR(r.unstable[1].phase_speed, 1.1324, 1e-3);
  // At 1.2 cm neither grows.
  EXPECT_TRUE(linear_stability_2d(s, c, 0.012).unstable.empty());
}

TEST(Linear2DPhysics, IllPosedBaseStateIsDetected) {
  const Material m;
  const MuCurve jop(CurveKind::Jop, m, 4e-3);
  const SteadyState sj = steady_state(jop, degrees_to_radians(28.5), 4e-3);
  const IllPosednessReport bad = probe_ill_posedness(sj, jop);
  EXPECT_TRUE(bad.C_positive);
  EXPECT_TRUE(bad.ill_posed_base_state) << bad.message;
  EXPECT_GT(bad.growth_hat_N2, 3.0 * bad.growth_hat_N1);

  const MuCurve reg(CurveKind::Regularised, m, 4e-3);
  const SteadyState sr = steady_state(reg, degrees_to_radians(28.5), 4e-3);
  const IllPosednessReport good = probe_ill_posedness(sr, reg);
  EXPECT_FALSE(good.C_positive);
  EXPECT_FALSE(good.ill_posed_base_state) << good.message;
  EXPECT_LT(good.growth_hat_N2, 0.0);
}

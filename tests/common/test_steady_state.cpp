// The steady Bagnold state (5.4)-(5.5), (7.1) and the generalised coefficients of (7.5)-(7.9).
#include <gtest/gtest.h>

#include <cmath>

#include "common/steady_state.hpp"

using namespace granbench;

TEST(SteadyState, BagnoldProfileHasUniformInertialNumberTanZeta) {
  const Material m;
  for (CurveKind kind : {CurveKind::Jop, CurveKind::Regularised}) {
    const MuCurve curve(kind, m);
    const SteadyState s = steady_state(curve, degrees_to_radians(24.0), 4e-3);
    for (double frac : {0.05, 0.3, 0.6, 0.9}) {
      const double z = frac * s.h0, h = 1e-7 * s.h0;
      const double shear = (s.velocity(z + h) - s.velocity(z - h)) / (2.0 * h);
      // (2.8) in simple shear: 2|D| = |du/dz|.
      const double I = m.d * shear / std::sqrt(s.pressure(z) / m.rho_star);
      EXPECT_NEAR(I / s.I_zeta, 1.0, 1e-7);
      EXPECT_NEAR(curve.mu(I), std::tan(s.zeta), 1e-7);
    }
  }
}

TEST(SteadyState, DepthAverageOfBagnoldProfileIsUMean) {
  const MuCurve curve(CurveKind::Regularised, Material{});
  const SteadyState s = steady_state(curve, degrees_to_radians(28.5), 4e-3);
  // Composite Simpson on a grid refined towards the surface (u has a sqrt singularity in u').
  const int n = 20000;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * s.velocity(s.h0 * i / n);
  }
  const double mean = sum * (s.h0 / n) / 3.0 / s.h0;
  EXPECT_NEAR(mean / s.u_mean, 1.0, 1e-9);
  EXPECT_NEAR(s.u_surface / s.u_mean, 5.0 / 3.0, 1e-14);
  EXPECT_NEAR(s.Fr, 2.0 * s.h0 / (5.0 * s.material.d) * s.I_zeta * std::sqrt(s.material.phi),
              1e-12);  // (7.1)
  EXPECT_NEAR(s.pressure(0.0), s.material.bulk_density() * s.material.g * s.h0 * std::cos(s.zeta),
              1e-9);
}

TEST(SteadyState, GeneralisedCoefficientsEqualThePapersForJop) {
  const Material m;
  const MuCurve curve(CurveKind::Jop, m);
  const double zeta = degrees_to_radians(26.0);
  const SteadyState s = steady_state(curve, zeta, 3e-3);
  const double tz = std::tan(zeta);
  const double nu_75 = 5.0 * m.d / (9.0 * m.I0) * std::sqrt(m.g) * std::sin(zeta) /
                       std::sqrt(m.phi * std::cos(zeta)) * (m.mu_d - tz) / (tz - m.mu_s);  // (7.5)
  EXPECT_NEAR(s.nu / nu_75, 1.0, 1e-12);
  const double gamma = 2.0 * std::sqrt(m.phi) * m.I0 * s.h0 / (5.0 * s.Fr * m.d);    // (7.9b)
  const double Gamma = gamma * (m.mu_d - m.mu_s) / ((1.0 + gamma) * (1.0 + gamma));  // (7.9a)
  EXPECT_NEAR(s.gamma / gamma, 1.0, 1e-12);
  EXPECT_NEAR(s.Gamma / Gamma, 1.0, 1e-12);
  EXPECT_NEAR(s.R, s.u_mean * std::sqrt(s.h0) / nu_75, 1e-9 * s.R);  // (7.6)
}

TEST(SteadyState, NoSteadyFlowOutsideTheCurvesRange) {
  const MuCurve jop(CurveKind::Jop, Material{});
  EXPECT_THROW(steady_state(jop, degrees_to_radians(15.0), 4e-3), CurveRangeError);
  EXPECT_THROW(steady_state(jop, degrees_to_radians(30.0), 4e-3), CurveRangeError);
  EXPECT_NO_THROW(
      steady_state(MuCurve(CurveKind::Regularised, Material{}), degrees_to_radians(30.0), 4e-3));
}

TEST(SteadyState, WellPosednessFlagFollowsC) {
  const MuCurve jop(CurveKind::Jop, Material{});
  EXPECT_TRUE(steady_state(jop, degrees_to_radians(24.0), 4e-3).well_posed);
  // At 28.5 deg Jop's I_zeta is above I2N (§6.2): ill posed.
  EXPECT_FALSE(steady_state(jop, degrees_to_radians(28.5), 7e-4).well_posed);
}

// C(I) (3.9): neutral points, signs between them, the limits of §4, the neutral curves (4.2)-(4.5).
#include <gtest/gtest.h>

#include <cmath>

#include "common/ill_posedness.hpp"
#include "common/neutral_points.hpp"

using namespace granbench;

namespace {
const CurveKind kAll[] = {CurveKind::Jop, CurveKind::Regularised, CurveKind::LowI,
                          CurveKind::KamrinKoval, CurveKind::Holyoake};
}

TEST(WellPosedness, CVanishesAtNeutralPointsAndHasTheRightSignAround) {
  for (CurveKind kind : kAll) {
    const MuCurve c(kind, Material{});
    const auto w = analyse_well_posedness(c);
    ASSERT_FALSE(w.neutral.empty()) << curve_name(kind);
    for (double r : w.neutral) EXPECT_NEAR(ill_posedness_C(c, r), 0.0, 1e-10) << curve_name(kind);
    // Sample each decade: C <= 0 inside a well-posed interval, > 0 outside.
    for (double e = -10.0; e <= 2.5; e += 0.01) {
      const double I = std::pow(10.0, e);
      bool inside = false;
      bool near_root = false;
      for (auto [lo, hi] : w.intervals) inside |= (I > lo && I < hi);
      for (double r : w.neutral) near_root |= std::abs(I / r - 1.0) < 1e-6;
      if (near_root) continue;
      if (inside)
        EXPECT_LE(ill_posedness_C(c, I), 0.0) << curve_name(kind) << " I = " << I;
      else
        EXPECT_GT(ill_posedness_C(c, I), 0.0) << curve_name(kind) << " I = " << I;
    }
  }
}

TEST(WellPosedness, JopIsIllPosedAtBothEndsRegularisedOnlyAtHighI) {
  const auto jop = analyse_well_posedness(MuCurve(CurveKind::Jop, Material{}));
  ASSERT_EQ(jop.intervals.size(), 1u);
  EXPECT_GT(jop.intervals[0].first, 0.0);
  const auto reg = analyse_well_posedness(MuCurve(CurveKind::Regularised, Material{}));
  ASSERT_EQ(reg.intervals.size(), 1u);
  EXPECT_EQ(reg.intervals[0].first, 0.0);
  EXPECT_GT(reg.I_max_wellposed, jop.I_max_wellposed);  // the I^2 term extends the range (§6)
}

TEST(WellPosedness, SmallInertialNumberLimitsOfSection4) {
  // mu(0) = A0 != 0: C -> A0^2 (4.1). The Jop curve has A0 = mu_s.
  const Material m;
  const MuCurve jop(CurveKind::Jop, m);
  EXPECT_NEAR(ill_posedness_C(jop, 1e-12), m.mu_s * m.mu_s, 1e-9);
  // mu = A I^n: C -> 4 n (n - 1).
  for (double n : {1.0, 2.0, 3.0}) {
    const double A = 0.7, I = 1e-8;
    const double mu = A * std::pow(I, n), I_dmu = n * A * std::pow(I, n);
    EXPECT_NEAR(ill_posedness_C(mu, I_dmu), 4.0 * n * (n - 1.0), 1e-12) << "n = " << n;
  }
}

TEST(WellPosedness, NeutralCurvesSolveTheOde42AndHaveCZero) {
  for (int sign : {+1, -1}) {
    const NeutralCurve curve = neutral_curve_through(0.01, 0.4, sign);
    EXPECT_NEAR(curve.I_of_mu(0.4), 0.01, 1e-14);
    for (double mu : {0.1, 0.3, 0.6, 1.0, 1.3}) {
      const double I = curve.I_of_mu(mu);
      // d ln I/dmu by central differences (I spans ~80 decades, ln I does not), compared with
      // (4.2) written as d ln I/dmu = 1/(I dmu/dI).
      const double h = 1e-6;
      const double dlnI =
          (std::log(curve.I_of_mu(mu + h)) - std::log(curve.I_of_mu(mu - h))) / (2.0 * h);
      const double slope = neutral_slope(mu, I, sign);
      EXPECT_NEAR(dlnI * I * slope, 1.0, 1e-7) << "sign " << sign << " mu " << mu;
      EXPECT_NEAR(ill_posedness_C(mu, I * slope), 0.0, 1e-12);  // (4.2) is C = 0
    }
  }
}

TEST(WellPosedness, ImaxIsTheLargestIOfTheUpperNeutralCurve) {
  // I_max = I_-^N(sqrt 2) on the neutral curve through (I2N, mu(I2N)) (§4).
  const MuCurve jop(CurveKind::Jop, Material{});
  const auto w = analyse_well_posedness(jop);
  ASSERT_TRUE(w.I2N.has_value());
  const double mu2 = jop.mu(*w.I2N);
  const auto curve = neutral_curve_through(*w.I2N, mu2, -1);
  EXPECT_NEAR(I_max_from(*w.I2N, mu2) / curve.I_of_mu(std::sqrt(2.0)), 1.0, 1e-12);
}

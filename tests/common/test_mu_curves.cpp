// mu(I) curves: analytic derivatives, inverses, continuity of the regularised curve, limits.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "common/mu_curves.hpp"

using namespace granbench;

namespace {
const CurveKind kAll[] = {CurveKind::Jop, CurveKind::Regularised, CurveKind::LowI,
                          CurveKind::KamrinKoval, CurveKind::Holyoake};
std::vector<double> sample_I() {
  std::vector<double> I;
  for (double e = -7.0; e <= 1.0; e += 0.25) I.push_back(std::pow(10.0, e));
  return I;
}
}  // namespace

TEST(MuCurves, AnalyticDerivativeMatchesCentralDifference) {
  for (CurveKind kind : kAll) {
    const MuCurve c(kind, Material{});
    for (double I : sample_I()) {
      if (c.junction_I() > 0.0 && std::abs(I / c.junction_I() - 1.0) < 1e-3) continue;  // kink
      const double h = 1e-5 * I;
      const double fd = (c.mu(I + h) - c.mu(I - h)) / (2.0 * h);
      // Truncation O(h^2) plus the round-off of the difference quotient, eps mu / h.
      const double roundoff = 4.0 * std::numeric_limits<double>::epsilon() * c.mu(I) / h;
      EXPECT_NEAR(c.dmu_dI(I), fd, 1e-7 * std::abs(fd) + roundoff)
          << curve_name(kind) << " at I = " << I;
    }
  }
}

TEST(MuCurves, CombinedValueAndLogSlopeMatchTheSeparateOnes) {
  for (CurveKind kind : kAll) {
    const MuCurve c(kind, Material{});
    std::vector<double> points = sample_I();
    if (c.junction_I() > 0.0)  // both sides of the junction of the low-I branch
      points.insert(points.end(), {c.junction_I() * (1.0 - 1e-9), c.junction_I() * (1.0 + 1e-9)});
    for (double I : points) {
      const auto [mu, slope] = c.mu_with_log_slope(I);
      const double expected = I * c.dmu_dI(I) / c.mu(I);
      EXPECT_NEAR(mu, c.mu(I), 1e-14 * c.mu(I)) << curve_name(kind) << " at I = " << I;
      EXPECT_NEAR(slope, expected, 1e-13 * std::abs(expected) + 1e-300)
          << curve_name(kind) << " at I = " << I;
    }
  }
}

// The batch form is the 2D model's: it must give each value bitwise as the scalar form, on both
// branches, at the junction, at I <= 0 and at the inf/NaN lanes it is documented to accept.
TEST(MuCurves, BatchValueAndLogSlopeAreBitwiseTheScalarOnes) {
  for (CurveKind kind : kAll) {
    const MuCurve c(kind, Material{});
    std::vector<double> I = sample_I();
    if (c.junction_I() > 0.0)
      I.insert(I.end(),
               {c.junction_I(), c.junction_I() * (1.0 - 1e-12), c.junction_I() * (1.0 + 1e-12)});
    I.insert(I.end(), {0.0, -1e-3, 3.7, 250.0});
    // several lengths: the vectorised loop's remainder lanes too
    for (std::size_t n : {I.size(), std::size_t(1), std::size_t(7), I.size() - 3}) {
      std::vector<double> mu(n), slope(n);
      c.mu_with_log_slope_many(std::span(I.data(), n), mu, slope);
      for (std::size_t j = 0; j < n; ++j) {
        const auto [m, s] = c.mu_with_log_slope(I[j]);
        EXPECT_EQ(mu[j], m) << curve_name(kind) << " at I = " << I[j];
        EXPECT_EQ(slope[j], s) << curve_name(kind) << " at I = " << I[j];
      }
    }
    // lanes of +inf or NaN are accepted; a lane of finite I beside them is unchanged
    std::vector<double> odd = {std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::quiet_NaN(), 0.3};
    std::vector<double> mu(3), slope(3);
    c.mu_with_log_slope_many(odd, mu, slope);
    EXPECT_EQ(mu[2], c.mu_with_log_slope(0.3).mu) << curve_name(kind);
    EXPECT_EQ(slope[2], c.mu_with_log_slope(0.3).log_slope) << curve_name(kind);
  }
}

TEST(MuCurves, InverseOfCurveIsIdentity) {
  for (CurveKind kind : kAll) {
    const MuCurve c(kind, Material{});
    for (double I : sample_I()) {
      const double mu = c.mu(I);
      if (!(mu > c.mu_min() && mu < c.mu_max())) continue;
      // Where the curve is nearly flat (mu -> mu_s or mu_d) the inverse is ill conditioned:
      // compare in mu, where the root finder works, and in I with the conditioning allowed for.
      const double I_back = c.inverse(mu);
      EXPECT_NEAR(c.mu(I_back), mu, 1e-13) << curve_name(kind) << " at I = " << I;
      const double cond = std::abs(mu / (I * c.dmu_dI(I)));
      EXPECT_NEAR(I_back / I, 1.0, 1e-12 * std::max(1.0, cond)) << curve_name(kind);
    }
  }
}

TEST(MuCurves, JopInverseMatchesClosedForm) {
  const Material m;
  const MuCurve c(CurveKind::Jop, m);
  for (double mu : {0.35, 0.4, 0.5, 0.55}) {
    const double exact = m.I0 * (mu - m.mu_s) / (m.mu_d - mu);  // (2.12) inverted
    EXPECT_NEAR(c.inverse(mu) / exact, 1.0, 1e-12);
  }
}

TEST(MuCurves, InverseOutsideRangeIsAClearError) {
  const MuCurve jop(CurveKind::Jop, Material{});
  EXPECT_THROW(jop.inverse(0.3), CurveRangeError);  // below mu_s
  EXPECT_THROW(jop.inverse(0.6), CurveRangeError);  // above mu_d
  const MuCurve reg(CurveKind::Regularised, Material{});
  EXPECT_THROW(reg.inverse(-0.1), CurveRangeError);
  EXPECT_NO_THROW(reg.inverse(0.9));  // the I^2 term makes mu unbounded
}

TEST(MuCurves, RegularisedCurveIsContinuousAtJunctionAndVanishesAtZero) {
  for (CurveKind kind : {CurveKind::Regularised, CurveKind::LowI}) {
    const MuCurve c(kind, Material{});
    const double Ij = c.junction_I();
    ASSERT_GT(Ij, 0.0);
    const double below = c.mu(Ij * (1.0 - 1e-12)), above = c.mu(Ij * (1.0 + 1e-12));
    EXPECT_NEAR(below, above, 1e-10) << curve_name(kind);
    // mu -> 0 as I -> 0, logarithmically (5.2): mu(1e-300) is small but nonzero.
    EXPECT_LT(c.mu(1e-300), 0.06);
    EXPECT_LT(c.mu(1e-300), c.mu(1e-100));
    EXPECT_EQ(c.mu(0.0), 0.0);
  }
}

TEST(MuCurves, RegularisedJunctionMatchesPaperConstants) {
  // The Gerris input for §7 uses I1N = 0.003962813 and A_- = 15640.68 for table 1 values.
  const MuCurve c(CurveKind::Regularised, Material{});
  EXPECT_NEAR(c.junction_I(), 0.003962813, 1e-9);
  EXPECT_NEAR(c.A_minus(), 15640.68, 0.01);
}

TEST(MuCurves, NamesRoundTripAndUnknownNameThrows) {
  for (CurveKind kind : kAll) EXPECT_EQ(parse_curve_name(curve_name(kind)), kind);
  EXPECT_THROW(parse_curve_name("bogus"), std::invalid_argument);
}

// Linear accuracy of the depth-averaged solver: the growth rate and phase speed
// of a seeded normal mode (7.10), measured spectrally, match the exact relation (7.11) within
// 0.5 % at wavelengths across the unstable band, and the decay rate past the cutoff; long waves
// decay for F < 2/3 and grow for F > 2/3 (7.11); with chi = 5/4 the solver follows the
// chi-generalised relation.
#include <gtest/gtest.h>

#include "analysis/comparison/depthavg_linear_run.hpp"
#include "analysis/theory/dispersion.hpp"
#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"

namespace granbench {
namespace {

struct Case {
  double angle_deg, h0;
};

SteadyState base_state(const Case& c, const MuCurve& curve) {
  return steady_state(curve, degrees_to_radians(c.angle_deg), c.h0);
}

TEST(DepthAvgLinear, GrowthAndSpeedMatchExactAcrossUnstableBandAndBeyondCutoff) {
  const Material m;
  const MuCurve curve(CurveKind::Regularised, m, 4e-3);
  const SteadyState s = base_state({28.5, 4e-3}, curve);
  const auto kc = cutoff_k_hat(DispersionParams::from(s, 1.0));
  ASSERT_TRUE(kc.has_value());
  const double Lc = Lx_from_k_hat(s, *kc);  // about 1.96 cm
  depthavg::LinearRunParams p;
  p.nx = 160;
  // Four unstable wavelengths from near the cutoff to long waves, and one decaying one.
  for (double Lx : {1.5 * Lc, 0.05, 0.12, 0.4, 0.6 * Lc}) {
    const auto r = depthavg::linear_run(s, curve, 1.0, Lx, p);
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_TRUE(r.measured.found()) << r.measured.reason;
    EXPECT_EQ(r.exact.growth_rate > 0.0, Lx > Lc);
    EXPECT_LT(r.growth_relative_error(), 5e-3)
        << "Lx " << Lx << ": measured " << r.measured.growth_rate << ", exact "
        << r.exact.growth_rate;
    EXPECT_LT(r.speed_relative_error(), 5e-3)
        << "Lx " << Lx << ": measured " << r.measured.phase_speed << ", exact "
        << r.exact.phase_speed;
  }
}

TEST(DepthAvgLinear, LongWavesDecayBelowCriticalFroudeAndGrowAbove) {
  const Material m;
  for (const Case c : {Case{25.0, 2e-3}, Case{25.0, 4e-3}}) {
    const MuCurve curve(CurveKind::Regularised, m, c.h0);
    const SteadyState s = base_state(c, curve);
    const double Lx = 250.0 * c.h0;  // k_hat = 0.025: long waves
    depthavg::LinearRunParams p;
    p.nx = 64;
    const auto r = depthavg::linear_run(s, curve, 1.0, Lx, p);
    ASSERT_TRUE(r.ok) << r.message;
    const bool supercritical = s.Fr > critical_froude(1.0);  // 2/3
    EXPECT_EQ(r.measured.growth_rate > 0.0, supercritical) << "F = " << s.Fr;
    EXPECT_LT(r.growth_relative_error(), 5e-3) << "F = " << s.Fr;
  }
}

TEST(DepthAvgLinear, BagnoldShapeFactorFollowsItsRelation) {
  const Material m;
  const MuCurve curve(CurveKind::Regularised, m, 4e-3);
  const SteadyState s = base_state({28.5, 4e-3}, curve);
  // With chi = 5/4 the growth rate is ~1/500 of the wave frequency, so it takes a finer grid
  // and tighter tolerance than chi = 1 to reach 0.5 % (the error still falls at third order).
  depthavg::LinearRunParams p;
  p.nx = 192;
  p.t_end = 1.0;
  for (double Lx : {0.08, 0.2}) {
    const auto r = depthavg::linear_run(s, curve, 1.25, Lx, p);
    const auto plug = dispersion_mode(s, 1.0, Lx);
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_LT(r.growth_relative_error(), 5e-3) << "Lx " << Lx;
    EXPECT_LT(r.speed_relative_error(), 5e-3) << "Lx " << Lx;
    // The shape factor matters: the chi = 1 relation is far from what the chi = 5/4 solver gives.
    EXPECT_GT(std::fabs(r.measured.phase_speed - plug.phase_speed), 0.1 * plug.phase_speed);
  }
}

}  // namespace
}  // namespace granbench

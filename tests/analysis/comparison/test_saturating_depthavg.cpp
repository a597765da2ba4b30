// DepthAvgSettings::limited_where_it_saturates: compare's and sweep's depth-averaged runs keep
// central slopes while the seeded wave stays within the measurement's linear bound (5 % of h0)
// and switch to van Albada's limiter when it grows past it before the run's end; a chosen limiter
// is kept. And a saturating 40-degree wave measured through the limiter: within 0.25 % of (7.11)
// (measured -0.10 % on 128 cells).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/comparison/compare.hpp"
#include "analysis/theory/dispersion.hpp"

using namespace granbench;

namespace {
ChuteCase chute(double angle_deg, double a0, double t_end) {
  ChuteCase c;
  c.angle_deg = angle_deg;
  c.Lx = 0.08;
  c.a0 = a0;
  c.t_end = t_end;
  return c;
}

double growth_711(const ChuteCase& c) {
  return dispersion_mode(c.steady(), 1.0, c.Lx).growth_rate;
}
}  // namespace

TEST(SaturatingDepthAvg, SlopesAreLimitedOnlyWhereTheSeedGrowsPastTheLinearBound) {
  using depthavg::Reconstruction;
  const DepthAvgSettings central;
  // The main job's wave: 1e-6 m growing at 1.23 1/s reaches 1.2e-5 m by 2 s, under 2e-4 m.
  const ChuteCase main_job = chute(28.5, 1e-6, 2.0);
  EXPECT_EQ(central.limited_where_it_saturates(main_job, growth_711(main_job)).reconstruction,
            Reconstruction::Central);
  // The same wave to 10 s (2.2e-1 m) and at 40 degrees to 2 s (7.98 1/s: past 2e-4 m at 0.66 s).
  const ChuteCase long_run = chute(28.5, 1e-6, 10.0), steep = chute(40.0, 1e-6, 2.0);
  EXPECT_EQ(central.limited_where_it_saturates(long_run, growth_711(long_run)).reconstruction,
            Reconstruction::VanAlbada);
  EXPECT_EQ(central.limited_where_it_saturates(steep, growth_711(steep)).reconstruction,
            Reconstruction::VanAlbada);
  // The bound itself: the seed grown to exactly 5 % of h0 by t_end is still linear.
  const double rate = growth_711(steep);
  const ChuteCase at_bound = chute(40.0, 1e-6, std::log(0.05 * 0.004 / 1e-6) / rate * 0.999);
  EXPECT_EQ(central.limited_where_it_saturates(at_bound, rate).reconstruction,
            Reconstruction::Central);
  // A decaying wave is never limited; a chosen limiter is kept.
  EXPECT_EQ(central.limited_where_it_saturates(steep, -rate).reconstruction,
            Reconstruction::Central);
  DepthAvgSettings mc;
  mc.reconstruction = Reconstruction::MC;
  EXPECT_EQ(mc.limited_where_it_saturates(steep, rate).reconstruction, Reconstruction::MC);
}

TEST(SaturatingDepthAvg, ASteepSlopesWaveIsMeasuredThroughTheLimiterAndTheRunCompletes) {
  // 40 degrees, 8 cm, 1e-6 m to 1.5 s: the wave saturates at about 7 mm. With central slopes the
  // fronts oscillate and the run stalls at 1.05 s (depthavg/solver.hpp); limited, it completes.
  const ChuteCase c = chute(40.0, 1e-6, 1.5);
  DepthAvgSettings s;
  s.nx = 128;
  s = s.limited_where_it_saturates(c, growth_711(c));
  ASSERT_EQ(s.reconstruction, depthavg::Reconstruction::VanAlbada);
  const ModelRun r = run_depthavg(c, s);
  EXPECT_EQ(r.outcome, RunOutcome::Completed) << r.message;
  MeasureOptions opt;
  const Theories t = exact_theories(c);
  opt.seeded_phase_speed = t.exact.phase_speed;
  const Measurement m = measure(r.series, opt);
  ASSERT_TRUE(m.spectral.found()) << m.spectral.reason;
  EXPECT_NEAR(m.spectral.growth_rate, t.exact.growth_rate, 0.0025 * t.exact.growth_rate);
  EXPECT_NEAR(m.spectral.phase_speed, t.exact.phase_speed, 1e-4 * t.exact.phase_speed);
  // The same run with central slopes does not complete.
  DepthAvgSettings unlimited = s;
  unlimited.reconstruction = depthavg::Reconstruction::Central;
  EXPECT_EQ(run_depthavg(c, unlimited).outcome, RunOutcome::Diverged);
}

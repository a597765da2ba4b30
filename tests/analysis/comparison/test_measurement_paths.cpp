// `granbench run` (both models: measure_surface_series), `compare` and `sweep` (measure) report
// one measurement: the same series with the same options gives bit-identical numbers, windows and
// reasons through both paths.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/comparison/compare.hpp"
#include "analysis/spectral/surface_measurement.hpp"

using namespace granbench;

namespace {

// The surface wave of the §7 case at Lx = 8 cm (2D theory: 1.089 1/s at 1.138 m/s) beating with a
// slow wave at 0.3195 m/s that starts at 5 % of it.
SurfaceSeries two_waves(std::size_t nt) {
  const double Lx = 0.08, h0 = 4e-3, k = 2.0 * std::numbers::pi / Lx, dt = 0.005;
  SurfaceSeries s = SurfaceSeries::uniform_grid(Lx, 64, h0);
  std::vector<double> h(64);
  for (std::size_t n = 0; n < nt; ++n) {
    const double t = n * dt;
    for (std::size_t j = 0; j < h.size(); ++j)
      h[j] = h0 + 2e-5 * std::exp(1.089 * t) * std::cos(k * (s.x[j] - 1.138 * t)) +
             1e-6 * std::exp(5.82 * t) * std::cos(k * (s.x[j] - 0.3195 * t) - 1.0);
    s.append(t, h);
  }
  return s;
}

void expect_same(const SurfaceMeasurement& a, const SurfaceMeasurement& b) {
  EXPECT_EQ(a.found(), b.found());
  EXPECT_EQ(a.reason, b.reason);
  if (!a.found()) return;
  EXPECT_EQ(a.growth_rate, b.growth_rate);
  EXPECT_EQ(a.phase_speed, b.phase_speed);
  EXPECT_EQ(a.t_first, b.t_first);
  EXPECT_EQ(a.t_last, b.t_last);
  EXPECT_EQ(a.relative_residual, b.relative_residual);
  ASSERT_EQ(a.modes.size(), b.modes.size());
  for (std::size_t i = 0; i < a.modes.size(); ++i) {
    EXPECT_EQ(a.modes[i].growth_rate, b.modes[i].growth_rate);
    EXPECT_EQ(a.modes[i].phase_speed, b.modes[i].phase_speed);
    EXPECT_EQ(a.modes[i].amplitude, b.modes[i].amplitude);
  }
}

}  // namespace

TEST(MeasurementPaths, RunAndCompareGiveTheSameNumbers) {
  MeasureOptions opt;
  opt.seeded_phase_speed = 1.138;  // what run --model twod and compare pass: the 2D theory's
  const SurfaceSeries s = two_waves(161);
  const SurfaceMeasurement run = measure_surface_series(s, opt);
  const Measurement compare = measure(s, opt);
  ASSERT_TRUE(run.found()) << run.reason;
  EXPECT_EQ(run.modes.size(), 2u);
  EXPECT_NEAR(run.growth_rate, 1.089, 1e-6);
  expect_same(run, compare.spectral);
  // And a series too short to measure: the same null and reason through both.
  const SurfaceSeries shrt = two_waves(10);
  expect_same(measure_surface_series(shrt, opt), measure(shrt, opt).spectral);
  EXPECT_FALSE(measure(shrt, opt).spectral.found());
}

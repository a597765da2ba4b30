// The saturated-wave measurement (saturated_wave.hpp) on travelling analytic profiles with exact
// answers: a rollwave-like front (tanh) with a linear back, and a sine. Amplitude, largest slope,
// 10-90 % front width, speed and flux against their exact values, and their errors falling with
// the grid over three resolutions.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "analysis/spectral/saturated_wave.hpp"
#include "common/surface_series.hpp"

namespace granbench {
namespace {

constexpr double pi = std::numbers::pi;

// One period of a rollwave-like profile around its front at xi = 0, on [-L/2, L/2):
//   h = h0 - (A/2) tanh(xi/w) + A xi/L,
// a front of height about A and half-width w facing +x, and a linear back that makes the profile
// periodic (value and slope match at +-L/2 to within exp(-L/w)).
struct FrontProfile {
  double L = 0.08, h0 = 4e-3, A = 1e-3, w = 2e-3;

  double operator()(double xi) const {
    xi = std::remainder(xi, L);  // into [-L/2, L/2]
    return h0 - 0.5 * A * std::tanh(xi / w) + A * xi / L;
  }
  // the steepest point is the front, xi = 0: |h'| = A/(2w) - A/L
  double max_slope() const { return A / (2.0 * w) - A / L; }
  // h' = 0 where sech^2(xi/w) = 2w/L; crest at -xi_e, trough at +xi_e
  double xi_extreme() const { return w * std::acosh(std::sqrt(L / (2.0 * w))); }
  double amplitude() const { return (*this)(-xi_extreme()) - (*this)(xi_extreme()); }
  // 10-90 % width: the profile is monotone between crest and trough; bisection for each level
  double width() const {
    const double lo = (*this)(xi_extreme()), a = amplitude();
    auto solve = [&](double level) {
      double left = -xi_extreme(), right = xi_extreme();  // h(left) > level > h(right)
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (left + right);
        ((*this)(mid) > level ? left : right) = mid;
      }
      return 0.5 * (left + right);
    };
    return solve(lo + 0.1 * a) - solve(lo + 0.9 * a);
  }
};

// The profile translating at speed c, sampled on nx cells every dt; u_mean = (c h - K)/h, so that
// the flux q = c h - K (the kinematic flux of a travelling wave) averages to c h0 - K exactly.
SurfaceSeries travelling(const std::function<double(double)>& profile, double L, double h0,
                         std::size_t nx, double c, double dt, std::size_t nt, double K) {
  SurfaceSeries s = SurfaceSeries::uniform_grid(L, nx, h0);
  std::vector<double> h(nx), u(nx);
  for (std::size_t n = 0; n < nt; ++n) {
    const double t = 1.0 + n * dt;
    for (std::size_t j = 0; j < nx; ++j) {
      h[j] = profile(s.x[j] - 0.013 - c * t);
      u[j] = (c * h[j] - K) / h[j];
    }
    s.append(t, h, u);
  }
  return s;
}

constexpr double kSpeed = 1.15, kDt = 0.0035, kK = 2e-3;

TEST(SaturatedWave, TanhFrontExactAnswers) {
  const FrontProfile f;
  const auto s = travelling(f, f.L, f.h0, 512, kSpeed, kDt, 40, kK);
  const SaturatedWave w = measure_saturated_wave(s, 1.05);
  EXPECT_EQ(w.samples, 25u);  // t = 1 + n dt >= 1.05: n = 15 .. 39
  EXPECT_TRUE(w.reason.empty()) << w.reason;
  EXPECT_NEAR(w.amplitude, f.amplitude(), 1e-4 * f.amplitude());
  EXPECT_NEAR(w.max_slope, f.max_slope(), 2e-3 * f.max_slope());
  EXPECT_NEAR(w.front_width, f.width(), 2e-3 * f.width());
  EXPECT_NEAR(w.wave_speed, kSpeed, 1e-9);
  EXPECT_EQ(w.speed_mode, 1);
  EXPECT_NEAR(w.mean_flux, kSpeed * f.h0 - kK, 1e-12);
  EXPECT_NEAR(w.mean_depth, f.h0, 1e-12);
  EXPECT_LT(w.amplitude_spread, 1e-3 * w.amplitude);
  ASSERT_EQ(w.amplitude_history.size(), 40u);

  // The wave frame: the last sample with its steepest point at xi = 0 is the profile itself.
  ASSERT_EQ(w.xi.size(), 512u);
  EXPECT_TRUE(std::is_sorted(w.xi.begin(), w.xi.end()));
  EXPECT_GE(w.xi.front(), -0.5 * f.L);
  EXPECT_LT(w.xi.back(), 0.5 * f.L);
  double worst = 0.0;
  for (std::size_t j = 0; j < w.xi.size(); ++j)
    worst = std::max(worst, std::fabs(w.h_frame[j] - f(w.xi[j])));
  EXPECT_LT(worst, 1e-3 * f.A);
}

TEST(SaturatedWave, FrontFacingUpstreamIsMeasuredTheSame) {
  // The mirror image (front facing -x, moving -x): same amplitude, slope and width, speed -c.
  const FrontProfile f;
  const auto mirror = [&](double x) { return f(-x); };
  const auto s = travelling(mirror, f.L, f.h0, 512, -kSpeed, kDt, 10, 0.0);
  const SaturatedWave w = measure_saturated_wave(s, 0.0);
  EXPECT_NEAR(w.max_slope, f.max_slope(), 2e-3 * f.max_slope());
  EXPECT_NEAR(w.front_width, f.width(), 2e-3 * f.width());
  EXPECT_NEAR(w.wave_speed, -kSpeed, 1e-9);
  const ProfileShape p = measure_profile(s.h_at(0), s.Lx);
  EXPECT_EQ(p.front_sign, 1.0);
}

TEST(SaturatedWave, SineExactAnswers) {
  // h = h0 + a sin(k x): amplitude 2a, slope a k, width 2 asin(0.8)/k; a second harmonic
  // would be followed too, but the fundamental dominates here.
  const double L = 0.06, h0 = 4e-3, a = 2e-4, k = 2.0 * pi / L;
  const auto sine = [&](double x) { return h0 + a * std::sin(k * x); };
  const auto s = travelling(sine, L, h0, 256, 0.9, 0.004, 12, 1e-3);
  const SaturatedWave w = measure_saturated_wave(s, 0.0);
  EXPECT_NEAR(w.amplitude, 2.0 * a, 1e-5 * a);
  EXPECT_NEAR(w.max_slope, a * k, 1e-4 * a * k);
  EXPECT_NEAR(w.front_width, 2.0 * std::asin(0.8) / k, 1e-3 * 2.0 * std::asin(0.8) / k);
  EXPECT_NEAR(w.wave_speed, 0.9, 1e-10);
}

TEST(SaturatedWave, DominantHarmonicGivesTheSpeed) {
  // Two identical fronts per domain: the fundamental is empty, mode 2 carries the wave.
  const FrontProfile f{.L = 0.04};
  const auto s = travelling(f, 0.08, f.h0, 256, kSpeed, kDt / 2, 10, 0.0);
  const SaturatedWave w = measure_saturated_wave(s, 0.0);
  EXPECT_EQ(w.speed_mode, 2);
  EXPECT_NEAR(w.wave_speed, kSpeed, 1e-9);
}

TEST(SaturatedWave, ErrorsFallWithTheGrid) {
  // The front is resolved by w/dx = 1.6, 3.2 and 6.4 cells: the errors of the slope (parabola
  // through face differences), the width (linear crossings) and the amplitude (parabola through
  // the extremes) fall at least as the square of dx (each halving of dx divides them by more than
  // 3); the speed and flux are exact up to the aliasing of a front 1.6 cells wide.
  const FrontProfile f;
  double previous[3] = {0.0, 0.0, 0.0};
  for (std::size_t nx : {std::size_t{64}, std::size_t{128}, std::size_t{256}}) {
    const auto s = travelling(f, f.L, f.h0, nx, kSpeed, kDt, 8, kK);
    const SaturatedWave w = measure_saturated_wave(s, 0.0);
    const double errors[3] = {std::fabs(w.max_slope / f.max_slope() - 1.0),
                              std::fabs(w.front_width / f.width() - 1.0),
                              std::fabs(w.amplitude / f.amplitude() - 1.0)};
    for (int q = 0; q < 3; ++q) {
      if (previous[q] > 0.0) {
        EXPECT_LT(errors[q], previous[q] / 3.0) << "quantity " << q << ", nx " << nx;
      }
      previous[q] = errors[q];
    }
    EXPECT_LT(errors[0], 0.1);  // the coarsest grid already gives the slope to 10 %
    EXPECT_NEAR(w.wave_speed, kSpeed, 1e-6 * kSpeed);
    EXPECT_NEAR(w.mean_flux, kSpeed * f.h0 - kK, 1e-8 * kK);
    std::printf("nx %zu: slope %.2e width %.2e amplitude %.2e speed %.2e\n", nx, errors[0],
                errors[1], errors[2], std::fabs(w.wave_speed / kSpeed - 1.0));
  }
}

TEST(SaturatedWave, NoSpeedFromOneSampleNoFluxWithoutVelocity) {
  SurfaceSeries s = SurfaceSeries::uniform_grid(0.08, 64, 4e-3);
  std::vector<double> h(64);
  const FrontProfile f;
  for (std::size_t j = 0; j < 64; ++j) h[j] = f(s.x[j]);
  s.append(0.0, h);
  const SaturatedWave w = measure_saturated_wave(s, 0.0);
  EXPECT_TRUE(std::isnan(w.wave_speed));
  EXPECT_TRUE(std::isnan(w.mean_flux));
  EXPECT_NE(w.reason.find("two samples"), std::string::npos);
  EXPECT_NE(w.reason.find("velocity"), std::string::npos);
  EXPECT_TRUE(to_json(w)["wave_speed"].is_null());
  EXPECT_THROW(measure_saturated_wave(s, 1.0), std::invalid_argument);
}

TEST(SaturatedWave, FlatProfileHasNoFront) {
  SurfaceSeries s = SurfaceSeries::uniform_grid(0.08, 32, 4e-3);
  const std::vector<double> h(32, 4e-3);
  s.append(0.0, h);
  s.append(0.1, h);
  const SaturatedWave w = measure_saturated_wave(s, 0.0);
  EXPECT_EQ(w.amplitude, 0.0);
  EXPECT_EQ(w.max_slope, 0.0);
  EXPECT_TRUE(std::isnan(w.front_width));
  EXPECT_TRUE(std::isnan(w.wave_speed));
  EXPECT_NE(w.reason.find("flat"), std::string::npos);
}

}  // namespace
}  // namespace granbench

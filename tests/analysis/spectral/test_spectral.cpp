// The spectral analyses on synthetic SurfaceSeries with known answers: growth rate and phase speed
// of a mode (surface_measurement.hpp, including an automatically found window before saturation),
// and the paper's estimator (7.12). The wave speed's tests are in test_wave_speed.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/spectral/growth_estimator_712.hpp"
#include "analysis/spectral/spectral_growth.hpp"
#include "analysis/spectral/surface_measurement.hpp"
#include "common/real_fft.hpp"
#include "common/surface_series.hpp"

namespace granbench {
namespace {

constexpr double pi = std::numbers::pi;

// h = h0 + A(t) cos(k (x - c t) + phase) on nx cells, nt samples every dt.
template <class Amplitude>
SurfaceSeries travelling(double Lx, std::size_t nx, int mode, double c, Amplitude A, double dt,
                         std::size_t nt, double h0 = 4e-3) {
  SurfaceSeries s = SurfaceSeries::uniform_grid(Lx, nx, h0);
  const double k = 2.0 * pi * mode / Lx;
  std::vector<double> h(nx);
  for (std::size_t n = 0; n < nt; ++n) {
    const double t = n * dt;
    for (std::size_t j = 0; j < nx; ++j) h[j] = h0 + A(t) * std::cos(k * (s.x[j] - c * t) + 0.3);
    s.append(t, h);
  }
  return s;
}

TEST(RealFFT, RoundTripAndModeAmplitude) {
  RealFFT fft(16);
  std::vector<double> x(16);
  for (std::size_t j = 0; j < 16; ++j) x[j] = 1.0 + 0.5 * std::cos(2.0 * pi * 3.0 * j / 16.0);
  const auto X = fft.forward(x);
  EXPECT_NEAR(std::abs(X[3]), 0.5 * 16 / 2.0, 1e-12);
  EXPECT_NEAR(X[0].real(), 16.0, 1e-12);
  const auto y = fft.inverse(X);
  for (std::size_t j = 0; j < 16; ++j) EXPECT_NEAR(y[j] / 16.0, x[j], 1e-14);
}

TEST(SpectralGrowth, ExactExponentialTravellingWave) {
  const double sigma = 1.3, c = 0.84;
  for (int mode : {1, 3}) {
    const auto s = travelling(
        0.08, 64, mode, c, [&](double t) { return 1e-6 * std::exp(sigma * t); }, 0.004, 200);
    MeasureOptions opt;
    opt.mode = mode;
    const auto g = measure_surface_series(s, opt);
    ASSERT_TRUE(g.found()) << g.reason;
    EXPECT_NEAR(g.growth_rate, sigma, 1e-10);
    EXPECT_NEAR(g.phase_speed, c, 1e-10);
    EXPECT_GT(g.log_amplitude_r2, 0.999999);
    EXPECT_EQ(g.first, 20u);  // after the first tenth of the run
    EXPECT_EQ(g.last, 199u);
  }
}

TEST(SpectralGrowth, WindowStopsBeforeSaturation) {
  // Exponential growth at rate 2 up to t = 2, then saturation at a constant amplitude. Without the
  // linear bound and the transient skip, the residual rule alone must end the window.
  const double sigma = 2.0;
  auto A = [&](double t) {
    const double lin = 1e-5 * std::exp(sigma * t);
    const double cap = 1e-5 * std::exp(sigma * 2.0);
    return lin / std::pow(1.0 + std::pow(lin / cap, 4.0), 0.25);
  };
  const auto s = travelling(0.08, 64, 1, 0.8, A, 0.01, 500);
  MeasureOptions opt;
  opt.linear_bound = 0.0;
  opt.transient = 0.0;
  const auto g = measure_surface_series(s, opt);
  ASSERT_TRUE(g.found()) << g.reason;
  EXPECT_NEAR(g.growth_rate, sigma, 0.01 * sigma);
  EXPECT_LT(g.t_last, 2.0);
  EXPECT_GT(g.t_last - g.t_first, 1.0);
  EXPECT_NEAR(g.phase_speed, 0.8, 1e-9);
}

TEST(SpectralGrowth, FitLineReportsExactLine) {
  const std::vector<double> t = {0, 1, 2, 3, 4}, y = {1, 3, 5, 7, 9};
  const auto f = fit_line(t, y, 1, 4);
  EXPECT_NEAR(f.slope, 2.0, 1e-14);
  EXPECT_NEAR(f.intercept, 1.0, 1e-13);
  EXPECT_NEAR(f.r2, 1.0, 1e-14);
  EXPECT_NEAR(f.rms_residual, 0.0, 1e-12);
}

TEST(Estimator712, GrowthOfTheMaximumHeight) {
  const double sigma = 1.1;
  const auto s = travelling(
      0.08, 128, 1, 0.8, [&](double t) { return 1e-5 * std::exp(sigma * t); }, 0.01, 300);
  const auto e = growth_estimate_712(s, 0.5, 2.5);
  // max over cells of a moving cosine differs from its amplitude by O((k dx)^2): 1e-3 here.
  EXPECT_NEAR(e.growth_rate, sigma, 1e-3 * sigma);
  EXPECT_NEAR(e.fit.slope, sigma, 1e-3 * sigma);
  EXPECT_THROW(growth_estimate_712(s, 5.0, 6.0), std::invalid_argument);
}

}  // namespace
}  // namespace granbench

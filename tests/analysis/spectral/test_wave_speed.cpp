// The wave speed (wave_speed.hpp: the phase speed of the dominant Fourier mode) on synthetic
// series with exact answers: a steep profile translated rigidly, both ways; the case that made the
// cross-correlation of successive samples fail (a fundamental with a slow short component, sampled
// like the 2D 12 cm rollwave); the same number through `run`'s measurement and through the
// saturated-wave measurement; and the series it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "analysis/spectral/measurement.hpp"
#include "analysis/spectral/saturated_wave.hpp"
#include "analysis/spectral/wave_speed.hpp"
#include "common/surface_series.hpp"

namespace granbench {
namespace {

constexpr double pi = std::numbers::pi;

// A steep periodic rollwave-like profile (the Fourier series of a smoothed sawtooth), translated
// without change of shape at speed c, a non-integer number of cells per sample.
SurfaceSeries sawtooth(double c) {
  const double Lx = 0.08, dt = 0.0037;
  const std::size_t nx = 256;
  SurfaceSeries s = SurfaceSeries::uniform_grid(Lx, nx, 4e-3);
  std::vector<double> h(nx);
  for (int n = 0; n < 20; ++n) {
    for (std::size_t j = 0; j < nx; ++j) {
      double v = 0.0;
      for (int m = 1; m <= 30; ++m)
        v += std::exp(-0.01 * m * m) / m * std::sin(2.0 * pi * m * (s.x[j] - c * n * dt) / Lx);
      h[j] = 4e-3 + 5e-4 * v;
    }
    s.append(n * dt, h);
  }
  return s;
}

TEST(WaveSpeed, RigidTranslationIsExactBothWays) {
  for (double c : {0.8371, -0.8371}) {
    const auto w = wave_speed(sawtooth(c), 0.0, 1.0);
    EXPECT_EQ(w.pairs, 19u);
    EXPECT_EQ(w.per_pair.size(), 19u);
    EXPECT_EQ(w.mode, 1);
    EXPECT_NEAR(w.speed, c, 1e-9 * std::fabs(c));
    EXPECT_LT(w.spread, 1e-9 * std::fabs(c));
    EXPECT_EQ(w.t_from, 0.0);
    EXPECT_NEAR(w.t_to, 19 * 0.0037, 1e-15);
  }
}

// The fundamental at c plus mode 5 moving at 0.3 m/s with 0.3 of its amplitude, on the 2D
// 12 cm rollwave's grid and sampling (240 cells on 0.12 m, a sample every 6.9 ms, the wave moving
// 15 cells per sample; the last sample closer, as at a run's end). The cross-correlation of
// successive samples put this wave at 0.547 m/s (its peak pulled towards the short component's
// 4 cells per sample), as it put the real run at 0.55 m/s; the fundamental's phase turn is exact.
constexpr double kLx = 0.12, kDt = 6.9e-3, kC = 1.087, kA1 = 3.2e-4, kH0 = 4e-3;

SurfaceSeries fundamental_with_slow_ripple(std::size_t nt) {
  SurfaceSeries s = SurfaceSeries::uniform_grid(kLx, 240, kH0);
  const double k1 = 2.0 * pi / kLx, k5 = 5.0 * k1;
  std::vector<double> h(240);
  for (std::size_t n = 0; n < nt; ++n) {
    const double t = n + 1 < nt ? n * kDt : (n - 1 + 0.96) * kDt;
    for (std::size_t j = 0; j < 240; ++j)
      h[j] = kH0 + kA1 * std::sin(k1 * (s.x[j] - kC * t)) +
             0.3 * kA1 * std::sin(k5 * (s.x[j] - 0.3 * t) + 0.7);
    s.append(t, h);
  }
  return s;
}

TEST(WaveSpeed, SlowShortComponentDoesNotPullTheSpeed) {
  const SurfaceSeries s = fundamental_with_slow_ripple(40);
  const auto w = wave_speed(s, 0.0, 1.0);
  EXPECT_EQ(w.mode, 1);
  EXPECT_EQ(w.pairs, 39u);
  EXPECT_NEAR(w.speed, kC, 1e-9 * kC);
  for (double c : w.per_pair) EXPECT_NEAR(c, kC, 1e-9 * kC);
  EXPECT_LT(w.spread, 1e-9 * kC);
  // A window that holds only part of the series: its samples, its pairs.
  const auto part = wave_speed(s, 10 * kDt, 20 * kDt + 1e-12);
  EXPECT_EQ(part.pairs, 10u);
  EXPECT_NEAR(part.speed, kC, 1e-9 * kC);
}

TEST(WaveSpeed, RunAndSaturatedMeasurementsReportTheSameSpeed) {
  // `run`'s measurement (last fifth, at least 8 samples) and the saturated-wave measurement over
  // the same samples are the same function: the same number, the same mode.
  const SurfaceSeries s = fundamental_with_slow_ripple(60);
  const Measurement m = measure(s);
  ASSERT_TRUE(m.wave.has_value());
  EXPECT_EQ(m.wave->pairs, 12u);  // last fifth of 60 samples: 12 pairs
  EXPECT_NEAR(m.wave->speed, kC, 1e-9 * kC);
  const nlohmann::json j = to_json(m);
  EXPECT_NEAR(j["wave_speed"].get<double>(), kC, 1e-9 * kC);
  EXPECT_EQ(j["wave_mode"].get<int>(), 1);
  const SaturatedWave sat = measure_saturated_wave(s, m.wave->t_from, m.wave->t_to);
  EXPECT_EQ(sat.samples, m.wave->pairs + 1);
  EXPECT_EQ(sat.wave_speed, m.wave->speed);
  EXPECT_EQ(sat.speed_mode, m.wave->mode);
}

TEST(WaveSpeed, RefusesFlatSurfacesAndSingleSamples) {
  SurfaceSeries flat = SurfaceSeries::uniform_grid(0.08, 32, 4e-3);
  const std::vector<double> h(32, 4e-3);
  flat.append(0.0, h);
  flat.append(0.1, h);
  EXPECT_THROW(wave_speed(flat, 0.0, 1.0), std::invalid_argument);
  EXPECT_FALSE(measure(flat).wave.has_value());
  const SurfaceSeries s = sawtooth(0.8);
  EXPECT_THROW(wave_speed(s, 0.0, 0.001), std::invalid_argument);  // one sample
  EXPECT_THROW(wave_speed(s, 5.0, 6.0), std::invalid_argument);    // none
}

}  // namespace
}  // namespace granbench

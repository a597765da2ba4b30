// Both models against their exact linear theories on either side of the cutoff wavelength
// (§7 case, regularised curve, 28.5 deg, h0 = 4 mm). The 2D theory's cutoff lies between 1.2 and
// 1.5 cm, (7.11)'s at 1.96 cm: Lx = 1 cm is stable for every theory, Lx = 8 cm unstable for all.
// Each model is seeded with the eigenmode of its own theory and measured spectrally.
#include <gtest/gtest.h>

#include <iostream>

#include "analysis/comparison/compare.hpp"

using namespace granbench;

namespace {
ChuteCase chute(double Lx, double t_end) {
  ChuteCase c;
  c.Lx = Lx;
  c.t_end = t_end;
  return c;
}
}  // namespace

TEST(CutoffSides, DepthAveragedModelGrowsAboveAndDecaysBelowItsCutoff) {
  const DepthAvgSettings s;  // 256 cells, central slopes, chi = 1
  for (double Lx : {0.01, 0.08}) {
    const ChuteCase c = chute(Lx, 1.0);
    const Measurement m = measure(run_depthavg(c, s).series);
    const Theories t = exact_theories(c);
    EXPECT_EQ(m.spectral.growth_rate > 0.0, t.exact.growth_rate > 0.0) << "Lx = " << Lx;
    EXPECT_NEAR(m.spectral.growth_rate, t.exact.growth_rate, 0.01 * std::fabs(t.exact.growth_rate))
        << "Lx = " << Lx;
  }
}

TEST(CutoffSides, TwoDModelDecaysBelowTheCutoffOnTwoGrids) {
  // Lx = 1 cm: the 2D theory gives -1.46 1/s. The 2D runs show a beating of two waves at the
  // seeded wavenumber (docs/comparison.md), so the decay is judged by the fit of ln|h_k| over the
  // whole run, not by the automatic window. Measured: -7 1/s (40 x 16), -5 1/s (80 x 16).
  const ChuteCase c = chute(0.01, 0.4);
  const Theories t = exact_theories(c);
  ASSERT_LT(t.exact_2d.growth_rate, 0.0);
  for (int nx : {40, 80}) {
    TwodSettings s;
    s.nx = nx;
    s.nz = 16;
    const ModelRun r = run_twod(c, s);
    ASSERT_EQ(r.outcome, RunOutcome::Completed) << r.message;
    const Measurement m = measure(r.series);
    EXPECT_LT(m.whole_run.slope, 0.0) << nx << " x 16";
    EXPECT_LT(r.mass_error, 1e-12);
  }
}

TEST(CutoffSides, TwoDModelGrowsAboveTheCutoffAtTheRateAndSpeedOfTheory) {
  // Lx = 8 cm, seeded with the 2D eigenmode at the linear amplitude a0 = 0.02 mm, 32 cells per h0
  // with the surface mid-cell (the default grid). Theory: +1.089 1/s at 1.1380 m/s. The
  // verification record (docs/twod-validation.md §4, last subsection) measures this grid at
  // 1.054 1/s (cfl 0.4), with 1.055 and 1.056 at cfl 0.2 and 0.1, and 1.027 / 1.066 at 16 / 64
  // cells per h0 (over 0.15-0.6 s): the check is the growth within 10 % and the phase speed
  // within 0.5 %.
  const ChuteCase c = chute(0.08, 1.0);
  const Theories t = exact_theories(c);
  ASSERT_GT(t.exact_2d.growth_rate, 0.0);
  TwodSettings s;
  s.nx = 160;
  s.nz = 64;
  const ModelRun r = run_twod(c, s);
  ASSERT_EQ(r.outcome, RunOutcome::Completed) << r.message;
  const Measurement m = measure(r.series);
  EXPECT_NEAR(m.spectral.growth_rate, t.exact_2d.growth_rate, 0.10 * t.exact_2d.growth_rate);
  EXPECT_NEAR(m.spectral.phase_speed / t.exact_2d.phase_speed, 1.0, 0.005);
  EXPECT_LT(r.mass_error, 1e-12);
  std::cout << "twod 160x64, Lx = 8 cm: growth " << m.spectral.growth_rate << " 1/s (theory "
            << t.exact_2d.growth_rate << "), phase speed " << m.spectral.phase_speed
            << " m/s (theory " << t.exact_2d.phase_speed << ")\n";
}

// Both models against their exact linear theories on either side of the cutoff wavelength
// (§7 case, regularised curve, 28.5 deg, h0 = 4 mm). The 2D theory's cutoff lies between 1.2 and
// 1.5 cm, (7.11)'s at 1.96 cm: Lx = 1 cm is stable for every theory, Lx = 8 cm unstable for all.
// Each model is seeded with the eigenmode of its own theory and measured spectrally.
#include <gtest/gtest.h>

#include "compare.hpp"

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

TEST(CutoffSides, TwoDModelDecaysBelowTheCutoff) {
  // Lx = 1 cm: the 2D theory gives -1.46 1/s. 40 x 16 cells: dx = 0.25 mm, dz = 0.5 mm.
  const ChuteCase c = chute(0.01, 0.4);
  TwodSettings s;
  s.nx = 40;
  s.nz = 16;
  const ModelRun r = run_twod(c, s);
  ASSERT_EQ(r.outcome, RunOutcome::Completed) << r.message;
  const Measurement m = measure(r.series);
  const Theories t = exact_theories(c);
  ASSERT_LT(t.exact_2d.growth_rate, 0.0);
  EXPECT_LT(m.spectral.growth_rate, 0.0);
  EXPECT_LT(r.mass_error, 1e-12);
}

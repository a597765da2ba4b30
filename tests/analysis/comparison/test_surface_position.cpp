// The 2D growth rate should not depend on where the undisturbed surface sits in its cell: the
// theory's surface is a line, the grid's is a fill fraction f of one row. With the surface row's
// hydrostatic pressure force and the shear spacing at the corner below it (the defaults,
// twod/surface_row_pressure.cpp and twod/properties.cpp) the growth of the §7 wave (28.5 deg,
// h0 = 4 mm, Lx = 8 cm, eigenmode seed) varies by 2.95 % between f = 0, 1/4, 1/2, 3/4 at 16 cells
// per h0 (80 x 32, cfl 0.4), against 12.8 % without the shear spacing and 29 % with the standard
// MAC pressure force (docs/twod-validation.md §4). At the default 32 cells per h0 it is 2.2 %
// (4.9 % without), short of the 2 % issue 12 asks for; this test runs the coarse grid because
// the dependence is largest and cheapest to see there, and fails if either fix is undone.
// The seed is 0.02 mm here (0.08 of a cell), the former default of every command. At the present
// default, 1 um, the wave is linear for the interface cells too, and the dependence is larger:
// 9.7 % at 16 cells per h0 (0.961, 1.063, 1.045, 1.031 1/s at f = 0, 1/4, 1/2, 3/4; the surface
// on a face is the outlier) and 3.3 % at 32 (1.0503, 1.0853, 1.0723, 1.0602). A finite seed
// averages the response over the fills its surface sweeps (docs/twod-validation.md §2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <span>

#include "analysis/comparison/compare.hpp"
#include "analysis/spectral/spectral_growth.hpp"
#include "analysis/spectral/spectral_modes.hpp"

using namespace granbench;

namespace {
// Growth rate of the seeded wave: a two-wave matrix-pencil fit of the fundamental's Fourier
// coefficient over [0.15, 0.6] s (after the seed's transient), taking the wave nearest the
// theory's phase speed.
double growth_with_surface_at(double fill, double theory_speed) {
  ChuteCase c;
  c.a0 = 2e-5;
  c.t_end = 0.6;
  c.dt_out = 0.005;
  TwodSettings s;
  s.nx = 80;
  s.nz = 32;
  s.Lz_over_h0 = fill > 0.0 ? s.nz / (s.nz / 2 - 1 + fill) : 2.0;  // h0 = (nz/2 - 1 + f) dz
  const ModelRun r = run_twod(c, s);
  EXPECT_EQ(r.outcome, RunOutcome::Completed) << r.message;
  const auto hk = mode_amplitudes(r.series, 1);
  std::size_t first = 0;
  while (r.series.t[first] < 0.15 - 1e-9) ++first;
  const PencilFit fit =
      fit_exponentials(std::span(hk).subspan(first), r.series.t[1] - r.series.t[0], 2);
  const double k = 2.0 * std::numbers::pi / c.Lx;
  const auto seeded = std::min_element(fit.components.begin(), fit.components.end(),
                                       [&](const auto& a, const auto& b) {
                                         return std::fabs(-a.lambda.imag() / k - theory_speed) <
                                                std::fabs(-b.lambda.imag() / k - theory_speed);
                                       });
  return seeded->lambda.real();
}
}  // namespace

TEST(SurfacePosition, GrowthHardlyDependsOnWhereTheSurfaceSitsInItsCell) {
  const Theories t = exact_theories(ChuteCase{});
  std::vector<double> growth;
  for (double fill : {0.0, 0.25, 0.5, 0.75}) {
    growth.push_back(growth_with_surface_at(fill, t.exact_2d.phase_speed));
    std::cout << "80x32, surface at " << fill << " of its cell: growth " << growth.back()
              << " 1/s\n";
  }
  const auto [lo, hi] = std::minmax_element(growth.begin(), growth.end());
  const double spread = (*hi - *lo) / growth[2];
  std::cout << "spread " << 100 * spread << " % (theory " << t.exact_2d.growth_rate << " 1/s)\n";
  EXPECT_LT(spread, 0.04);  // 2.95 % measured; 12.8 % without the shear spacing
  for (double g : growth) EXPECT_NEAR(g, t.exact_2d.growth_rate, 0.10 * t.exact_2d.growth_rate);
}

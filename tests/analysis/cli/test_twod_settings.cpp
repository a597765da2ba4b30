// The one builder of the 2D solver's parameters (analysis/comparison/twod_settings.hpp): the
// `granbench run` command line that compare and sweep record for a 2D run (run_command.hpp),
// parsed by `run`'s own options, gives the same solver parameters and domain height as the
// settings it was made from, for every setting changed from its default (in process, no runs).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/cli/run_twod.hpp"
#include "analysis/comparison/growth_deficit_law.hpp"
#include "analysis/comparison/run_command.hpp"
#include "analysis/linear2d/eigenmode.hpp"

namespace granbench::cli {
namespace {

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

TEST(TwodSettings, OtherLengthsKeepThePresetsCellsAndAtMostItsDx) {
  // compare and sweep take the cells along x from here: a short domain keeps the preset's cells
  // (one wavelength of the seeded wave; the 2 cm wave had 40 cells with the dx rule alone), a
  // long one the preset's dx (0.5 mm at 160 cells over 8 cm), in multiples of 16.
  TwodSettings s;
  s.nx = 160;
  EXPECT_EQ(s.cells_along(0.02), 160);
  EXPECT_EQ(s.cells_along(0.08), 160);
  EXPECT_EQ(s.cells_along(0.12), 240);
  EXPECT_EQ(s.cells_along(0.24), 480);
  // rounded up to a multiple of 16, which the pressure multigrid can halve four times
  EXPECT_EQ(s.cells_along(0.09727272727272727), 208);  // 195 rounded up: dx 0.468 mm
  EXPECT_EQ(s.cells_along(0.1), 208);
  s.nx = 80;
  EXPECT_EQ(s.cells_along(0.01), 80);
  EXPECT_EQ(s.cells_along(0.16), 160);
}

TEST(TwodSettings, ShortWavesGetMoreCellsAcrossTheLayer) {
  // compare and sweep take nz from here: the preset's for waves of 7.5 h0 and longer, refined as
  // 7.5 h0 / wavelength below it (at most twice), in multiples of 16 for the multigrid.
  TwodSettings s;
  s.nz = 64;
  const double h0 = 4e-3;
  EXPECT_EQ(s.cells_across(0.08, h0), 64);
  EXPECT_EQ(s.cells_across(0.03, h0), 64);   // 7.5 h0
  EXPECT_EQ(s.cells_across(0.025, h0), 80);  // 76.8 rounded up
  EXPECT_EQ(s.cells_across(0.02, h0), 96);   // 5 h0: 48 cells per h0
  EXPECT_EQ(s.cells_across(0.01, h0), 128);  // 2.5 h0: capped at twice the preset's
  EXPECT_EQ(s.cells_across(0.025, 5e-3), 96);
  s.nz = 32;  // the coarse preset
  EXPECT_EQ(s.cells_across(0.02, h0), 48);
  // the domain stays about 2 h0 high with the surface mid-cell: 47.5 cells below it at 2 cm
  s.nz = 64;
  s.nz = s.cells_across(0.02, h0);
  EXPECT_NEAR(s.domain_height(h0) / s.nz * 47.5, h0, 1e-15);
}

// Near the 2D cutoff the deficit law raises nz to the fewest cells (a multiple of 16) on which it
// expects at most aimed_growth_deficit of the exact 2D growth, at most four times the preset's;
// every wave the law already trusts on the wavelength's grid keeps it.
TEST(TwodSettings, NearTheCutoffTheDeficitLawAddsCellsAcrossTheLayer) {
  auto law_grid = [](double angle, double h0, double Lx, int preset_nz, double aim) {
    ChuteCase c;
    c.angle_deg = angle;
    c.h0 = h0;
    const SteadyState base = c.steady();
    const double growth = linear2d::surface_eigenmode(base, c.make_curve(), Lx).growth_rate();
    TwodSettings s;
    s.nz = preset_nz;
    s.aimed_growth_deficit = aim;
    const int n = s.cells_across(Lx, base, growth);
    auto expected_share = [&](int nz) {
      TwodSettings t = s;
      t.nz = nz;
      return expected_twod_growth_deficit(base, t.domain_height(h0) / nz, Lx) / growth;
    };
    const int by_wavelength = s.cells_across(Lx, h0);
    EXPECT_EQ(n % 16, 0);
    EXPECT_GE(n, by_wavelength);
    EXPECT_LE(n, 4 * preset_nz);
    if (n > by_wavelength && n < 4 * preset_nz) {  // the fewest that meet the aim
      EXPECT_LE(expected_share(n), aim) << Lx;
      EXPECT_GT(expected_share(n - 16), aim) << Lx;
    }
    EXPECT_EQ(s.cells_across(Lx, base, NAN), by_wavelength);
    EXPECT_EQ(s.cells_across(Lx, base, -1.0), by_wavelength);
    return n;
  };
  // section 7 (28.5 degrees, 4 mm; cutoff near 1.38 cm), the default preset
  EXPECT_EQ(law_grid(28.5, 4e-3, 0.08, 64, 0.075), 64);
  EXPECT_EQ(law_grid(28.5, 4e-3, 0.03, 64, 0.075), 64);
  EXPECT_EQ(law_grid(28.5, 4e-3, 0.025, 64, 0.075), 80);
  EXPECT_EQ(law_grid(28.5, 4e-3, 0.02, 64, 0.075), 96);  // 6.4 % expected: kept
  EXPECT_EQ(law_grid(28.5, 4e-3, 0.016, 64, 0.075), 176);
  EXPECT_EQ(law_grid(28.5, 4e-3, 0.015, 64, 0.075), 256);  // 19.5 % expected on 128
  EXPECT_EQ(law_grid(28.5, 4e-3, 0.014, 64, 0.075), 256);  // the cap
  // the coarse preset aims at 3/4 of its 25 %
  EXPECT_EQ(law_grid(28.5, 4e-3, 0.015, 32, 0.1875), 128);
  // 28 degrees, 5 mm (cutoff near 1.75 cm): 2 cm was 12.2 % under on 128 cells
  EXPECT_EQ(law_grid(28.0, 5e-3, 0.02, 64, 0.075), 192);
  EXPECT_EQ(law_grid(28.0, 5e-3, 0.025, 64, 0.075), 96);
}

TEST(TwodSettings, RecordedRunCommandRebuildsTheSameSolverParameters) {
  ChuteCase c;
  c.angle_deg = 29.0;
  c.h0 = 5e-3;
  c.Lx = 0.06;
  c.material.mu_inf = 0.07;
  TwodSettings s;
  s.nx = 96;
  s.nz = 40;
  s.Lz_over_h0 = 2.3;
  s.eta_max = 3.5;
  s.eta_min = 2e-3;
  s.D_min = 1e-5;
  s.rho_light = 0.3;
  s.eta_light = 2e-4;
  s.mixing = twod::ViscosityMixing::Harmonic;
  s.cfl = 0.3;
  s.dt_max = 5e-4;
  s.tolerance = 1e-9;
  s.viscosity_passes = 2;
  const twod::SolverParams expected = twod_solver_params(c, s);

  std::vector<std::string> args = words(twod_run_command(c, s, 0.01));
  ASSERT_GE(args.size(), 2u);
  ASSERT_EQ(args[0] + " " + args[1], "granbench run");
  args.erase(args.begin(), args.begin() + 2);
  CLI::App app;
  RunOptions run;
  TwodOptions twod;
  add_run_options(app, run);
  add_twod_options(app, twod);
  std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector
  app.parse(args);
  double Lz = 0.0;
  const twod::SolverParams p = twod_run_params(run, twod, Lz);

  EXPECT_EQ(run.nx, std::size_t(s.nx));
  EXPECT_EQ(twod.settings.nz, s.nz);
  EXPECT_DOUBLE_EQ(Lz, s.domain_height(c.h0));
  EXPECT_DOUBLE_EQ(p.zeta, expected.zeta);
  const twod::Rheology &r = p.rheology, &e = expected.rheology;
  EXPECT_EQ(r.curve, e.curve);
  EXPECT_DOUBLE_EQ(r.material.mu_inf, e.material.mu_inf);
  EXPECT_DOUBLE_EQ(r.h0_for_curve, e.h0_for_curve);
  EXPECT_DOUBLE_EQ(r.eta_max, e.eta_max);
  EXPECT_DOUBLE_EQ(r.eta_min, e.eta_min);
  EXPECT_DOUBLE_EQ(r.D_min, e.D_min);
  EXPECT_DOUBLE_EQ(r.rho_light, e.rho_light);
  EXPECT_DOUBLE_EQ(r.eta_light, e.eta_light);
  EXPECT_EQ(r.mixing, e.mixing);
  EXPECT_DOUBLE_EQ(p.cfl, expected.cfl);
  EXPECT_DOUBLE_EQ(p.dt_max, expected.dt_max);
  EXPECT_DOUBLE_EQ(p.solver_tolerance, expected.solver_tolerance);
  EXPECT_EQ(p.viscosity_passes, expected.viscosity_passes);
  EXPECT_DOUBLE_EQ(p.velocity_limit, expected.velocity_limit);
}

}  // namespace
}  // namespace granbench::cli

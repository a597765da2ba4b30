// The one builder of the 2D solver's parameters (analysis/comparison/twod_settings.hpp): the
// `granbench run` command line that compare and sweep record for a 2D run (run_command.hpp),
// parsed by `run`'s own options, gives the same solver parameters and domain height as the
// settings it was made from, for every setting changed from its default (in process, no runs).
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/cli/run_twod.hpp"
#include "analysis/comparison/run_command.hpp"

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

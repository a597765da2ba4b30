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
// expects at most aimed_growth_deficit of the exact 2D growth, at most six times the preset's;
// every wave the law already trusts on the wavelength's grid keeps it. Where it refines, a wave
// that stays small (the seed grown at the exact rate over the run within h0/20) also gets a light
// layer of h0/4; a larger one keeps h0 of it, and so does a domain of given height.
struct SeedAndRun {
  double a0, t_end;
};
constexpr SeedAndRun kLinearRun{1e-6, 2.0};  // compare's and sweep's defaults
constexpr SeedAndRun kPaperRun{2e-4, 10.0};  // run's default: the paper's sine start, 10 s

TwodSettings law_grid(double angle, double h0, double Lx, int preset_nz, double aim,
                      SeedAndRun seed, double Lz_over_h0 = 0.0) {
  ChuteCase c;
  c.angle_deg = angle;
  c.h0 = h0;
  const SteadyState base = c.steady();
  const double growth = linear2d::surface_eigenmode(base, c.make_curve(), Lx).growth_rate();
  TwodSettings s;
  s.nz = preset_nz;
  s.aimed_growth_deficit = aim;
  s.Lz_over_h0 = Lz_over_h0;
  const TwodSettings r = s.refined_across(Lx, base, growth, seed.a0, seed.t_end);
  auto expected_share = [&](int nz) {
    TwodSettings t = r;
    t.nz = nz;
    return expected_twod_growth_deficit(base, t.domain_height(h0) / nz, Lx) / growth;
  };
  const int n = r.nz, by_wavelength = s.cells_across(Lx, h0);
  TwodSettings w = s;  // the wavelength's grid
  w.nz = by_wavelength;
  const double dz_by_wavelength = w.domain_height(h0) / by_wavelength;
  EXPECT_EQ(n % 16, 0);
  // no taller cells than the wavelength's grid's
  EXPECT_LE(r.domain_height(h0) / n, dz_by_wavelength * (1 + 1e-12)) << Lx;
  const int cap = static_cast<int>(TwodSettings::max_law_refinement) * preset_nz;
  EXPECT_LE(n, cap);
  const bool refined = expected_twod_growth_deficit(base, dz_by_wavelength, Lx) > aim * growth;
  const bool small = seed.a0 * std::exp(growth * seed.t_end) <= 0.05 * h0;
  EXPECT_EQ(r.light_layer_over_h0, refined && small && Lz_over_h0 == 0.0 ? 0.25 : 1.0) << Lx;
  if (!refined) {
    EXPECT_EQ(n, by_wavelength) << Lx;
  }
  if (refined && n < cap) {  // the fewest that meet the aim
    EXPECT_LE(expected_share(n), aim) << Lx;
    EXPECT_GT(expected_share(n - 16), aim) << Lx;
  }
  for (const double unknown : {double(NAN), -1.0}) {
    const TwodSettings by_length = s.refined_across(Lx, base, unknown, seed.a0, seed.t_end);
    EXPECT_EQ(by_length.nz, by_wavelength);
    EXPECT_EQ(by_length.light_layer_over_h0, 1.0);
  }
  return r;
}

TEST(TwodSettings, NearTheCutoffTheDeficitLawAddsCellsAcrossTheLayer) {
  auto nz = [](double angle, double h0, double Lx, int preset_nz, double aim, SeedAndRun seed) {
    return law_grid(angle, h0, Lx, preset_nz, aim, seed).nz;
  };
  // section 7 (28.5 degrees, 4 mm; cutoff near 1.370 cm), the default preset, under h0 of light
  // fluid (the paper's sine start grows beyond h0/20)
  EXPECT_EQ(nz(28.5, 4e-3, 0.08, 64, 0.075, kPaperRun), 64);
  EXPECT_EQ(nz(28.5, 4e-3, 0.03, 64, 0.075, kPaperRun), 64);
  EXPECT_EQ(nz(28.5, 4e-3, 0.025, 64, 0.075, kPaperRun), 80);
  EXPECT_EQ(nz(28.5, 4e-3, 0.02, 64, 0.075, kPaperRun), 96);  // 6.4 % expected: kept
  EXPECT_EQ(nz(28.5, 4e-3, 0.016, 64, 0.075, kPaperRun), 176);
  EXPECT_EQ(nz(28.5, 4e-3, 0.015, 64, 0.075, kPaperRun), 256);  // 19.5 % expected on 128
  EXPECT_EQ(nz(28.5, 4e-3, 0.014, 64, 0.075, kPaperRun), 384);  // the cap
  // the coarse preset aims at 3/4 of its 25 %
  EXPECT_EQ(nz(28.5, 4e-3, 0.015, 32, 0.1875, kPaperRun), 144);
  // 28 degrees, 5 mm (cutoff near 1.75 cm): 2 cm was 12.2 % under on 128 cells
  EXPECT_EQ(nz(28.0, 5e-3, 0.02, 64, 0.075, kPaperRun), 192);
  EXPECT_EQ(nz(28.0, 5e-3, 0.025, 64, 0.075, kPaperRun), 96);
  // The same waves seeded small, as compare and sweep run them: the grids the law keeps are the
  // same, and where it refines, the thin light layer gives the same cells per h0 in fewer rows.
  EXPECT_EQ(nz(28.5, 4e-3, 0.08, 64, 0.075, kLinearRun), 64);
  EXPECT_EQ(nz(28.5, 4e-3, 0.02, 64, 0.075, kLinearRun), 96);
  EXPECT_EQ(nz(28.5, 4e-3, 0.016, 64, 0.075, kLinearRun), 112);
  EXPECT_EQ(nz(28.5, 4e-3, 0.015, 64, 0.075, kLinearRun), 160);  // 127.5 cells per h0, as above
  EXPECT_EQ(nz(28.5, 4e-3, 0.014, 64, 0.075, kLinearRun), 384);  // the cap: 307 per h0
  EXPECT_EQ(nz(28.5, 4e-3, 0.015, 32, 0.1875, kLinearRun), 96);  // 76 per h0, under the cap
  EXPECT_EQ(nz(28.0, 5e-3, 0.02, 64, 0.075, kLinearRun), 128);
  EXPECT_EQ(nz(28.0, 5e-3, 0.025, 64, 0.075, kLinearRun), 96);
  // a domain of given height keeps it
  EXPECT_EQ(law_grid(28.5, 4e-3, 0.015, 64, 0.075, kLinearRun, 2.0).nz, 256);
}

// The thin light layer keeps the surface mid-cell: 306.5 cells below it at 1.4 cm on 384 rows.
TEST(TwodSettings, TheThinLightLayerKeepsTheSurfaceMidCell) {
  const TwodSettings r = law_grid(28.5, 4e-3, 0.014, 64, 0.075, kLinearRun);
  EXPECT_EQ(r.nz, 384);
  EXPECT_NEAR(r.domain_height(4e-3) / r.nz * 306.5, 4e-3, 1e-15);
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
  s.cfl = 0.8;  // (above the VOF's 1/2: allowed since the volume fractions sub-step)
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

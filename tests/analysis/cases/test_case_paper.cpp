// The paper's cases in full (ctest label `paper`, not in CI: tens of minutes), checked against
// the paper's claims (§5.2, §6.2, §7). The thresholds are the claims, not fits to our output:
//  - decelerating (figures 3-5): the regularised runs agree between resolutions, the Jop runs
//    disagree more. Judged by the largest difference while both grids flow: once the layer is at
//    rest the floor on |D| sets I for both curves alike (docs/paper-cases.md);
//  - high-speed (figure 8): the Jop runs are ill posed: they blow up or give grid-dependent flows
//    (the two resolutions more than 0.1 decade apart in I); the regularised runs converge on the
//    I_zeta of (6.3) (within 2 %) and agree between resolutions (within 0.01 decade);
//  - rollwaves (figures 9-12): the runs reach t = 10 s, conserve mass, and grow a wave, the
//    eigenmode start at the exact 2D theory's rate;
//  - figure 13: eigenmode seeding lands nearer the exact 2D theory than the paper's start.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_granbench.hpp"

namespace {

using granbench::testing::run_granbench;
namespace fs = std::filesystem;

// `stopped_runs_allowed`: a case whose claim is judged on the runs that completed may exit with
// the failure policy's 3 (a run stopped early) and still be checked.
nlohmann::json run_case(const std::string& name, bool stopped_runs_allowed = false) {
  const fs::path dir = fs::temp_directory_path() / ("granbench_paper_" + name);
  fs::remove_all(dir);
  const auto r =
      run_granbench("case " + name + " --json --quiet --out-dir " + dir.string(), "paper_" + name);
  if (stopped_runs_allowed && r.code == 3)
    std::cout << name << ": some runs stopped early\n" << r.err;
  else
    EXPECT_EQ(r.code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

double largest(const nlohmann::json& series) {
  double m = 0.0;
  for (const auto& v : series)
    if (!v.is_null()) m = std::max(m, v.get<double>());
  return m;
}

TEST(PaperCase, DeceleratingRegularisedIsGridIndependentJopIsNot) {
  const auto j = run_case("decelerating");
  // The largest difference between the curve's two grids while both still flow: in the few
  // milliseconds in which a layer comes to rest its I falls four decades, so a sample there
  // measures how far apart in time the two grids stop (both curves alike), not the rheology.
  auto largest_while_flowing = [&](const std::string& curve) {
    for (const auto& [key, series] : j["grid_dependence"].items()) {
      if (key.rfind(curve + "_", 0) != 0) continue;
      double m = 0.0;
      int flowing = 0;
      for (std::size_t n = 0; n < series["rms_log10_I"].size(); ++n)
        if (series["both_flowing"][n].get<bool>() && series["rms_log10_I"][n].is_number()) {
          m = std::max(m, series["rms_log10_I"][n].get<double>());
          ++flowing;
        }
      EXPECT_GE(flowing, 10) << key;  // the layer decelerates over more than 10 samples
      return m;
    }
    ADD_FAILURE() << "no grid dependence for " << curve;
    return 0.0;
  };
  const double jop = largest_while_flowing("jop");
  const double reg = largest_while_flowing("low-i");
  EXPECT_GT(jop, reg);
  EXPECT_LT(reg, 0.1);  // within a quarter of I between resolutions (0.1 decade)
}

TEST(PaperCase, HighSpeedRegularisedConvergesOnItsIzeta) {
  const auto j = run_case("high-speed");
  bool jop_diverged = false;
  for (const auto& r : j["runs"]) {
    if (r["curve"] == "jop") {
      jop_diverged = jop_diverged || r["status"] == "diverged";
    } else {
      EXPECT_EQ(r["status"], "completed");
      EXPECT_NEAR(r["final_bulk_I"].get<double>() / r["steady_I"].get<double>(), 1.0, 0.02) << r;
    }
  }
  const auto& gd = j["grid_dependence"];
  EXPECT_LT(largest(gd["regularised_64x16_vs_regularised_128x32"]["rms_log10_I"]), 0.01);
  if (!jop_diverged) {
    EXPECT_GT(largest(gd["jop_64x16_vs_jop_128x32"]["rms_log10_I"]), 0.1);
  }
}

// Figures 11-12: the runs reach 10 s and grow a wave. Grown: the surface's half range at 10 s is at
// least twice the start's a0 (the sine (7.2) starts at half range a0; the eigenmode start at a0
// too). The eigenmode start grows exponentially at the exact 2D theory's rate: its spectral fit
// within 10 % and its phase speed within 1 % (measured 0.9084 against 0.9739 1/s, -6.7 %, and
// 1.1412 against 1.1410 m/s; docs/paper-cases.md).
TEST(PaperCase, RollwavesRunToTenSecondsAndGrowAWave) {
  const struct {
    const char* name;
    double a0;  // the case file's a0 [m]
    bool eigenmode;
  } cases[] = {{"rollwave-8cm", 2e-4, false},
               {"rollwave-12cm", 2e-4, false},
               {"rollwave-12cm-eigenmode", 2e-5, true}};
  nlohmann::json eig;  // the eigenmode start's run, at Lx = 12 cm
  for (const auto& c : cases) {
    const auto j = run_case(c.name);
    const auto& run = j["run"];
    if (c.eigenmode) eig = run;
    EXPECT_EQ(run["status"], "completed") << c.name;
    EXPECT_NEAR(run["t_reached"].get<double>(), 10.0, 1e-9) << c.name;
    EXPECT_LT(std::abs(run["mass_error"].get<double>()), 1e-10) << c.name;
    EXPECT_GT(run["final_amplitude"].get<double>(), 2.0 * c.a0) << c.name;
  }
  const auto theory = run_granbench("dispersion --theory twod --Lx 0.12 --json --quiet", "theory");
  ASSERT_EQ(theory.code, 0) << theory.err;
  const auto mode = nlohmann::json::parse(theory.out)["modes"][0];
  ASSERT_TRUE(eig["growth_rate"].is_number()) << eig["reason"];
  EXPECT_NEAR(eig["growth_rate"].get<double>() / mode["growth_rate"].get<double>(), 1.0, 0.10);
  EXPECT_NEAR(eig["phase_speed"].get<double>() / mode["phase_speed"].get<double>(), 1.0, 0.01);
}

// Figure 13: the paper puts the "discrepancies in magnitude" of its 2D growth rates down to its
// start, a sine whose a0 is close to the saturated amplitude, and says the points follow the
// shape of the relation. Checked as that claim: every run completes (the long sine runs stopped
// before momentum was carried with the VOF step's mass fluxes), at every length the 2D theory
// calls unstable the eigenmode-seeded 2D wave grows and is nearer the exact 2D theory's rate than
// the paper's protocol's (7.12), and from 3 cm up it is within 10 % of it (measured on 3
// December: -6.6 % at 3 cm, -4.3 % at 4 cm, within 2.5 % from 6 cm up; 2 cm, under-resolved on
// the default grid, -16 %; the sine protocol -57 % to -103 %; docs/paper-cases.md).
TEST(PaperCase, Figure13EigenmodeSeedingIsNearerThe2DTheoryThanThePapersStart) {
  const auto j = run_case("figure13");
  int compared = 0;
  for (const auto& p : j["points"]) {
    const double exact = p["exact_2d"].get<double>();
    if (!(exact > 0.0)) continue;
    ASSERT_TRUE(p["eigenmode_vs_2d"].is_number()) << p;
    EXPECT_TRUE(p["eigenmode_message"].get<std::string>().empty()) << p;  // every one completes
    EXPECT_GT(p["eigenmode_spectral"].get<double>(), 0.0) << p;
    ASSERT_TRUE(p["sine_712_vs_2d"].is_number()) << p;  // every sine run completes its 3 s
    ++compared;
    EXPECT_LT(std::abs(p["eigenmode_vs_2d"].get<double>()),
              std::abs(p["sine_712_vs_2d"].get<double>()))
        << p;
    if (p["Lx"].get<double>() >= 0.03 - 1e-12) {
      EXPECT_LT(std::abs(p["eigenmode_vs_2d"].get<double>()), 0.10) << p;
    }
  }
  EXPECT_EQ(compared, 8);
}

}  // namespace

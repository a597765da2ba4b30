// The paper's cases in full (ctest label `paper`, not in CI: tens of minutes), checked against
// the paper's claims (§5.2, §6.2, §7). The thresholds are the claims, not fits to our output:
//  - decelerating (figures 3-5): the regularised runs agree between resolutions, the Jop runs
//    disagree more. Judged by the largest difference while both grids flow: once the layer is at
//    rest the floor on |D| sets I for both curves alike (docs/paper-cases.md);
//  - high-speed (figure 8): the Jop runs are ill posed: they blow up or give grid-dependent flows
//    (the two resolutions more than 0.1 decade apart in I), and their perturbations grow at least
//    twice as fast at each halving of the cell; the regularised runs converge on the I_zeta of
//    (6.3) (within 2 %), agree between resolutions (within 0.01 decade) and their perturbations
//    decay;
//  - rollwaves (figures 9-12): the runs reach t = 10 s, conserve mass, and grow a wave, the
//    eigenmode start at the exact 2D theory's rate;
//  - figure 13: eigenmode seeding lands nearer the exact 2D theory than the paper's start.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
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

// Figure 8's ill posedness, measured: the growth rate of the perturbation energy E of Jop's layer
// rises without bound as the grid is refined. The fastest-growing waves of an ill-posed problem
// are the shortest the grid holds and their rate grows in proportion to their wavenumber, so
// each halving of the cell at least doubles the rate. The case file's layer at about 16, 32 and 64
// cells across h0 (8 does not grow: docs/paper-cases.md), each run only to past its break-up:
// 0.25 s at 16 cells, 0.05 s at 32 and 64 (measured on 7 December: 101.6, 593.4, 2826.6 1/s).
//
// The regularised layer, run as long as Jop's coarsest (0.25 s) on 16 and 32 cells across h0, is
// well posed and its steady state damps every wave the domain holds (the exact 2D theory: -8.7
// 1/s for the longest): its E falls from the seed and stays below it, so the case's measure finds
// no growth. Measured on 7 December: from 7.6e-12 and 3.2e-11 to at most 2.4e-15 and 1.8e-14
// after the first 20 ms. (With the surface on a cell face, as the case file had it before, E rose
// to 3e-8 by 0.25 s instead: the case file says why it no longer is.) About 2 minutes on two cores.
TEST(PaperCase, HighSpeedJopGrowthRisesWithTheGridRegularisedDecays) {
  const fs::path cases = fs::temp_directory_path() / "granbench_paper_high_speed_growth";
  fs::remove_all(cases);
  fs::create_directories(cases);
  std::ifstream in(std::string(GRANBENCH_SOURCE_DIR) + "/cases/high-speed.toml");
  const std::string original((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
  auto variant = [&](const std::string& name, const std::string& curves, const std::string& t_end,
                     const std::string& samples, const std::string& nx, const std::string& nz) {
    std::string text = original;
    for (const auto& [from, to] :
         {std::pair<std::string, std::string>{"curves = [\"jop\", \"regularised\"]", curves},
          {"t_end = 5.0", t_end},
          {"samples = 51", samples},
          {"nx = [64, 128]", nx},
          {"nz = [16, 32]", nz}}) {
      const auto at = text.find(from);
      if (at == std::string::npos) {
        ADD_FAILURE() << "cases/high-speed.toml has no line '" << from << "'";
        return;
      }
      text.replace(at, from.size(), to);
    }
    std::ofstream(cases / (name + ".toml")) << text;
  };
  const std::string both = "curves = [\"jop\", \"regularised\"]";
  variant("high-speed-16", both, "t_end = 0.25", "samples = 251", "nx = [128]", "nz = [32]");
  variant("high-speed-jop-32-64", "curves = [\"jop\"]", "t_end = 0.05", "samples = 101",
          "nx = [256, 512]", "nz = [64, 128]");
  variant("high-speed-regularised-32", "curves = [\"regularised\"]", "t_end = 0.25",
          "samples = 251", "nx = [256]", "nz = [64]");
  std::map<int, double> jop_rate;  // by cells across h0
  int regularised_runs = 0;
  for (const std::string name :
       {"high-speed-16", "high-speed-jop-32-64", "high-speed-regularised-32"}) {
    const fs::path out = fs::temp_directory_path() / ("granbench_paper_" + name);
    fs::remove_all(out);
    const auto r = run_granbench("case " + name + " --json --quiet --cases-dir " + cases.string() +
                                     " --out-dir " + out.string(),
                                 "paper_" + name);
    ASSERT_EQ(r.code, 0) << r.err;
    const auto result = nlohmann::json::parse(r.out);
    for (const auto& run : result["runs"]) {
      EXPECT_EQ(run["status"], "completed") << run["label"];
      // nz / 2 names the grid: Lz = 48/23 h0, so nz = 32, 64, 128 hold 15.3, 30.7, 61.3 cells
      // across h0
      const int cells_per_h0 = run["nz"].get<int>() / 2;
      std::cout << run["label"] << ": largest E " << largest(run["perturbation_energy"]);
      if (run["curve"] == "jop") {
        const auto& growth = run["energy_growth"];
        ASSERT_TRUE(growth["rate"].is_number()) << run["label"] << ": " << growth;
        jop_rate[cells_per_h0] = growth["rate"].get<double>();
        std::cout << ", d ln E/dt = " << growth["rate"] << " 1/s over " << growth["window"]
                  << " s\n";
      } else {
        std::cout << "\n";
        const auto& E = run["perturbation_energy"];
        ASSERT_GE(E.size(), 2u);
        ASSERT_TRUE(E[0].is_number()) << run["label"];
        double E_after_start = 0.0;  // the largest E after t = 0
        for (std::size_t n = 1; n < E.size(); ++n) {
          ASSERT_TRUE(E[n].is_number()) << run["label"] << " at sample " << n;
          E_after_start = std::max(E_after_start, E[n].get<double>());
        }
        EXPECT_LT(E_after_start, E[0].get<double>()) << run["label"];
        EXPECT_TRUE(run["energy_growth"]["rate"].is_null()) << run["label"];
        ++regularised_runs;
      }
    }
  }
  ASSERT_EQ(jop_rate.size(), 3u);
  EXPECT_GT(jop_rate[32], 2.0 * jop_rate[16]);
  EXPECT_GT(jop_rate[64], 2.0 * jop_rate[32]);
  EXPECT_EQ(regularised_runs, 2);
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
// the paper's protocol's (7.12), and within 10 % of it at every length (the 2 cm wave on the
// cells across the layer that the preset gives a wave under 7.5 h0, TwodSettings::cells_across;
// docs/paper-cases.md has the figures).
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
    EXPECT_LT(std::abs(p["eigenmode_vs_2d"].get<double>()), 0.10) << p;
  }
  EXPECT_EQ(compared, 8);
}

}  // namespace

// The granbench command end to end: JSON values against the library, and bad input rejected
// with exit code 2, one line naming the option, and no output file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::ScratchDir;

granbench::testing::CommandResult run(const std::string& args) {
  return granbench::testing::run_granbench(args, "cli_foundation");
}

}  // namespace

TEST(CliFoundation, WellposedJsonHasTheDocumentedKeys) {
  const auto r = run("wellposed --curve regularised --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"curve", "I1N", "I2N", "well_posed_intervals", "A_minus", "I_max_wellposed"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_NEAR(j["I1N"].get<double>(), 0.003962813, 1e-9);
  EXPECT_TRUE(run("wellposed --curve jop --json").out.find("\"A_minus\": null") !=
              std::string::npos);
}

TEST(CliFoundation, SteadyAndDispersionJson) {
  auto r = run("steady --angle 28.5 --h0 0.004 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"I_zeta", "u_surface", "u_mean", "Fr", "R", "Gamma", "nu", "well_posed"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_NEAR(j["I_zeta"].get<double>(), 0.404574, 1e-6);
  r = run("dispersion --angle 28.5 --h0 0.004 --Lx 0.04 --Lx 0.08 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["modes"].size(), 2u);
  EXPECT_TRUE(j.contains("cutoff_Lx"));
  EXPECT_GT(j["modes"][1]["growth_rate"].get<double>(), 0.0);
}

TEST(CliFoundation, BadInputGivesOneLineExitTwoAndNoFile) {
  const ScratchDir dir("gb_bad_input");
  const std::string out = dir / "out.h5";
  struct Case {
    std::string args, option;
  };
  const Case cases[] = {
      {"wellposed --curve nonsense", "--curve"},
      {"steady --h0 -0.001", "--h0"},
      {"steady --h0 0", "--h0"},
      {"steady --angle 90", "--angle"},
      {"steady --angle 0", "--angle"},
      {"steady --angle abc", "--angle"},
      {"steady --curve jop --angle 35", "--angle"},
      {"dispersion --Lx -1", "--Lx"},
  };
  for (const auto& c : cases) {
    std::filesystem::remove(out);
    const auto r = run(c.args + " --out " + out);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_NE(r.err.find(c.option), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("valid"), std::string::npos) << r.err;  // names the valid range
    EXPECT_FALSE(std::filesystem::exists(out)) << c.args;
  }
}

// The text report that each command prints without --json (what a user reads first) completes:
// exit 0, and the lines that name its figures. The depth-averaged run's report read a key its
// JSON no longer had (linear_iterations, renamed linear_solves) and ended in an internal error,
// exit 1, while every JSON test passed.
TEST(CliFoundation, EveryCommandsTextReportCompletes) {
  const ScratchDir dir("gb_text_reports");
  const std::string out = dir / "out.h5";
  struct Case {
    std::string args, line;
  };
  const Case cases[] = {
      {"wellposed", "upper neutral point I2N"},
      {"steady", "I_zeta"},
      {"dispersion --Lx 0.08", "growth"},
      {"run --model depthavg --Lx 0.08 --nx 64 --t-end 0.5", "linear solves"},
      {"run --model depthavg --Lx 0.08 --nx 64 --t-end 0.5 --out " + out, "growth rate"},
      {"run --model twod --nx 32 --nz 16 --t-end 0.005 --checkpoint-every 0 --out " + out,
       "growth"},
      {"compare --nx 32 --nz 16 --nx-depthavg 32 --t-end 0.005 --out " + out, "twod"},
  };
  for (const auto& c : cases) {
    const auto r = run(c.args + " --quiet");
    EXPECT_EQ(r.code, 0) << c.args << "\n" << r.err;
    EXPECT_NE(r.out.find(c.line), std::string::npos) << c.args << "\n" << r.out;
  }
}

// --plot without an extension writes NAME.png, and the report names that file.
TEST(CliFoundation, APlotNamedWithoutExtensionIsWrittenAsPng) {
  const ScratchDir dir("gb_plot_name");
  const std::string stem = dir / "wellposed";
  const auto r = run("wellposed --plot " + stem);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(stem + ".png"));
  EXPECT_NE(r.out.find("figure written to " + stem + ".png"), std::string::npos) << r.out;
}

// `run --model twod` reports the seeded wave's exact 2D theory beside its measurement, the same
// numbers `dispersion --theory twod` gives, in its JSON and in its table.
TEST(CliFoundation, TwodRunShowsTheExact2DTheoryOfItsWave) {
  const auto theory = run("dispersion --theory twod --Lx 0.04 --json");
  ASSERT_EQ(theory.code, 0) << theory.err;
  const auto mode = nlohmann::json::parse(theory.out)["modes"][0];
  const std::string args = "run --model twod --Lx 0.04 --nx 32 --nz 16 --t-end 0.005 --quiet";
  const auto r = run(args + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["growth_rate_theory"].get<double>(), mode["growth_rate"].get<double>(), 1e-9);
  EXPECT_NEAR(j["phase_speed_theory"].get<double>(), mode["phase_speed"].get<double>(), 1e-9);
  const auto text = run(args);
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("exact 2D linear"), std::string::npos) << text.out;
}

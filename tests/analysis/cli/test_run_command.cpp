// Reproducibility from the output: `compare --json` gives, for each model, the `granbench run`
// command line that reproduces its run (analysis/comparison/run_command.hpp). Run alone, that
// command must report the same growth rate and phase speed to 1e-9 (relative): the same steps,
// the same series, the same measurement. A small 2D grid and a short run keep it to seconds; the
// Lx = 4 cm wave grows fast enough for both models to give a measured growth rate.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_granbench.hpp"

namespace {

using granbench::testing::run_granbench;

void expect_same_to_1e9(const nlohmann::json& a, const nlohmann::json& b, const char* key,
                        const std::string& model) {
  ASSERT_TRUE(a[key].is_number()) << model << " " << key << " not measured by compare: " << a;
  ASSERT_TRUE(b[key].is_number()) << model << " " << key << " not measured by run: " << b;
  const double x = a[key].get<double>(), y = b[key].get<double>();
  EXPECT_LE(std::fabs(x - y), 1e-9 * std::fabs(x))
      << model << " " << key << ": " << x << " vs " << y;
}

}  // namespace

TEST(RunCommand, EachModelsRunCommandReproducesItsGrowthRateAndPhaseSpeed) {
  const auto dir = std::filesystem::temp_directory_path() / "granbench_run_command";
  std::filesystem::create_directories(dir);
  const std::string h5 = (dir / "compare.h5").string(), png = (dir / "compare.png").string();
  const auto c = run_granbench(
      "compare --Lx 0.04 --nx 32 --nz 16 --nx-depthavg 64 --t-end 1.2 "
      "--angle 29 --json --quiet --out " +
          h5 + " --plot " + png,
      "run_command");
  ASSERT_EQ(c.code, 0) << c.err;
  const auto jc = nlohmann::json::parse(c.out);
  // the grids the runs took, as given
  EXPECT_EQ(jc["depthavg"]["cells"], nlohmann::json({64}));
  EXPECT_EQ(jc["twod"]["cells"], nlohmann::json({32, 16}));
  for (const std::string model : {"depthavg", "twod"}) {
    const auto& m = jc[model];
    ASSERT_TRUE(m["run_command"].is_string()) << model;
    const std::string cmd = m["run_command"].get<std::string>();
    ASSERT_EQ(cmd.rfind("granbench run ", 0), 0u) << cmd;
    const auto r = run_granbench(cmd.substr(std::string("granbench ").size()) + " --json --quiet",
                                 "run_command_" + model);
    ASSERT_EQ(r.code, 0) << cmd << "\n" << r.err;
    const auto jr = nlohmann::json::parse(r.out);
    expect_same_to_1e9(m, jr, "growth_rate", model);
    expect_same_to_1e9(m, jr, "phase_speed", model);
  }
  std::filesystem::remove_all(dir);
}

// On a steep slope the seeded wave saturates within the run, so compare limits the
// depth-averaged slopes (DepthAvgSettings::limited_where_it_saturates): it says so, the command
// completes (with central slopes that run stalls at 1.05 s), and the run command it records names
// the limiter and reproduces the measurement.
TEST(RunCommand, ASaturatingDepthAveragedRunNamesItsLimiterAndIsReproduced) {
  const auto dir = std::filesystem::temp_directory_path() / "granbench_run_command_steep";
  std::filesystem::create_directories(dir);
  const auto c = run_granbench(
      "compare --angle 40 --Lx 0.08 --nx 32 --nz 16 --nx-depthavg 128 "
      "--t-end 1.5 --json --quiet --out " +
          (dir / "c.h5").string() + " --plot " + (dir / "c.png").string(),
      "run_command_steep");
  ASSERT_EQ(c.code, 0) << c.err;
  const auto jc = nlohmann::json::parse(c.out);
  const auto& m = jc["depthavg"];
  EXPECT_EQ(m["limiter"], "vanalbada");
  EXPECT_TRUE(m["completed"].get<bool>());
  bool noted = false;
  for (const auto& w : jc["warnings"])
    noted = noted || w.get<std::string>().find("limits its slopes") != std::string::npos;
  EXPECT_TRUE(noted) << jc["warnings"];
  const std::string cmd = m["run_command"].get<std::string>();
  ASSERT_NE(cmd.find("--limiter vanalbada"), std::string::npos) << cmd;
  const auto r = run_granbench(cmd.substr(std::string("granbench ").size()) + " --json --quiet",
                               "run_command_steep_depthavg");
  ASSERT_EQ(r.code, 0) << cmd << "\n" << r.err;
  const auto jr = nlohmann::json::parse(r.out);
  expect_same_to_1e9(m, jr, "growth_rate", "depthavg");
  expect_same_to_1e9(m, jr, "phase_speed", "depthavg");
  std::filesystem::remove_all(dir);
}

// A seed at or above the linear bound is said to start there (not to pass the bound at a negative
// time), and its depth-averaged run is limited too.
TEST(RunCommand, ASeedAboveTheLinearBoundIsSaidToStartThere) {
  const auto dir = std::filesystem::temp_directory_path() / "granbench_run_command_large_seed";
  std::filesystem::create_directories(dir);
  const auto c = run_granbench(
      "compare --Lx 0.08 --nx 32 --nz 16 --nx-depthavg 64 --t-end 0.1 "
      "--a0 4e-4 --json --quiet --out " +
          (dir / "c.h5").string() + " --plot " + (dir / "c.png").string(),
      "run_command_large_seed");
  ASSERT_EQ(c.code, 0) << c.err;
  const auto jc = nlohmann::json::parse(c.out);
  EXPECT_EQ(jc["depthavg"]["limiter"], "vanalbada");
  std::string note;
  for (const auto& w : jc["warnings"])
    if (w.get<std::string>().find("limits its slopes") != std::string::npos) note = w;
  EXPECT_NE(note.find("starts at 0.1 h0"), std::string::npos) << note;
  EXPECT_EQ(note.find("t = -"), std::string::npos) << note;
  std::filesystem::remove_all(dir);
}

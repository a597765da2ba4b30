// The `granbench run` and `granbench sweep` commands for the depth-averaged model: bad options are
// rejected with exit code 2 and one line naming the option, without writing output; a short run
// and sweep produce the documented JSON keys.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "common/hdf5_file.hpp"
#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::h5_read_string_attribute;
using granbench::testing::CommandResult;
using granbench::testing::ScratchDir;

CommandResult granbench_cli(const std::string& args) {
  return granbench::testing::run_granbench(args, "depthavg_cli");
}

TEST(DepthAvgCli, BadOptionsAreRejectedNamingTheOption) {
  const ScratchDir dir("gb_cli_bad");
  const std::string out = dir / "out.h5";
  const std::pair<std::string, std::string> cases[] = {
      {"run --model depthavg --nx 2", "--nx"},
      {"run --model depthavg --chi 0.5", "--chi"},
      {"run --model depthavg --chi plug", "--chi"},
      {"run --model depthavg --limiter superbee", "--limiter"},
      {"run --model depthavg --a0 0.005", "--a0"},
      {"run --model depthavg --t-end -1", "--t-end"},
      {"run --model depthavg --rtol 2", "--rtol"},
      {"run --model depthavg --init cosine", "--init"},
      {"run --model nosuch", "--model"},
      {"run --model depthavg --curve jop --angle 10", "--angle"},
      {"sweep --model depthavg --Lx 0.1:0.05:3", "--Lx"},
      {"sweep --model depthavg --Lx 0.1:0.2", "--Lx"},
      {"sweep --model depthavg --jobs 0", "--jobs"},
  };
  for (const auto& [args, option] : cases) {
    const auto r = granbench_cli(args + " --out " + out);
    EXPECT_EQ(r.code, 2) << args;
    const std::string& err = r.err;
    EXPECT_NE(err.find(option), std::string::npos) << args << ": " << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << args << ": " << err;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
  }
}

TEST(DepthAvgCli, RunPrintsTheSharedJsonKeysAndWritesHdf5) {
  const ScratchDir dir("gb_cli_run");
  const std::string out = dir / "out.h5";
  const auto r = granbench_cli(
      "run --model depthavg --init eigenmode --a0 4e-6 --Lx 0.08 --nx 64 --t-end 0.3 "
      "--rtol 1e-8 --atol 1e-14 --json --out " +
      out);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"steps", "wall_seconds", "mass_error", "h_mean", "flux", "growth_rate", "phase_speed",
        "wave_speed", "wave_mode", "growth_rate_exact", "phase_speed_exact", "limiter"})
    EXPECT_TRUE(j.contains(key)) << key;
  // (--limiter auto: a seed of 4 um that grows 1.4-fold stays linear, so central slopes)
  EXPECT_EQ(j["limiter"], "central");
  EXPECT_NEAR(j["growth_rate"].get<double>(), j["growth_rate_exact"].get<double>(),
              0.02 * j["growth_rate_exact"].get<double>());
  EXPECT_LT(j["mass_error"].get<double>(), 1e-13);
  EXPECT_TRUE(std::filesystem::exists(out));
}

TEST(DepthAvgCli, AStalledRunSaysSoWithinSecondsAndNamesTheLimiter) {
  // 40 degrees, unlimited slopes: the fronts oscillate until CVODE's steps collapse. The run
  // stops as diverged (exit 3) with the stall and the way out in its one line, keeps its samples
  // in --out, and a limited reconstruction runs the same case to the end: van Albada asked for,
  // and the default (--limiter auto), which chooses it because the seed of 0.2 mm (5 % of h0)
  // grows from the start.
  const ScratchDir dir("gb_cli_stall");
  const std::string out = dir / "out.h5";
  const std::string args =
      "run --model depthavg --angle 40 --Lx 0.08 --nx 32 --t-end 0.1 --quiet --out " + out;
  const auto r = granbench_cli(args + " --limiter central");
  EXPECT_EQ(r.code, 3);
  const std::string& err = r.err;
  EXPECT_NE(err.find("the integration stalled"), std::string::npos) << err;
  EXPECT_NE(err.find("--limiter vanalbada"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_TRUE(std::filesystem::exists(out));
  std::filesystem::remove(out);
  const auto limited = granbench_cli(args + " --limiter vanalbada");
  EXPECT_EQ(limited.code, 0) << limited.err;
  std::filesystem::remove(out);
  const auto automatic = granbench_cli(args + " --json");
  ASSERT_EQ(automatic.code, 0) << automatic.err;
  const auto j = nlohmann::json::parse(automatic.out);
  EXPECT_EQ(j["limiter"], "vanalbada");
  EXPECT_EQ(j["limiter_option"], "auto");
  EXPECT_EQ(j["status"], "completed");
  EXPECT_EQ(h5_read_string_attribute(out, "/", "limiter"), "vanalbada");
}

TEST(DepthAvgCli, SweepReportsPointsBesideTheExactRelation) {
  const auto r = granbench_cli("sweep --model depthavg --Lx 0.05:0.1:2 --nx 128 --jobs 2 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["points"].size(), 2u);
  for (const auto& p : j["points"]) {
    for (const char* key :
         {"Lx", "growth_rate", "growth_rate_exact", "phase_speed", "phase_speed_exact"})
      EXPECT_TRUE(p.contains(key)) << key;
    EXPECT_NEAR(p["growth_rate"].get<double>(), p["growth_rate_exact"].get<double>(),
                0.01 * p["growth_rate_exact"].get<double>());
  }
}

}  // namespace

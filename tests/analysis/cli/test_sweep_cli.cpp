// `granbench sweep --model depthavg` end to end on the resumable engine: a re-run keeps the points
// of the output file and runs only the new ones; a stored sweep with other settings is refused
// (exit 2, one line naming --out); under `mpirun -np 2` the ranks share the points and the result
// equals the single-process run (skipped when the build has no MPI or mpirun is missing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::run_granbench;

// Cheap linear points: 64 cells, automatic run length.
const std::string kSweep = "sweep --model depthavg --nx 64 --jobs 1 --json ";

// The tests' files, in a directory of this process that goes when the tests end.
std::string temp_file(const std::string& name) {
  static const granbench::testing::ScratchDir dir("gb_sweep_cli");
  return dir / name;
}

// Points by Lx (rounded to micrometres).
std::map<long, nlohmann::json> by_Lx(const nlohmann::json& j) {
  std::map<long, nlohmann::json> m;
  for (const auto& p : j["points"]) m[std::lround(p["Lx"].get<double>() * 1e6)] = p;
  return m;
}

nlohmann::json sweep(const std::string& args, const std::string& launcher = "") {
  const auto r = run_granbench(kSweep + args, "sweep", launcher);
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

TEST(SweepCli, ResumesFromTheOutputFileAndRunsOnlyTheNewPoints) {
  const std::string out = temp_file("resume.h5");
  std::filesystem::remove(out);
  const auto first = sweep("--Lx 0.04:0.08:2 --out " + out);  // 0.04, 0.08
  ASSERT_EQ(first["points_run"], 2);
  const auto second = sweep("--Lx 0.04:0.08:3 --out " + out);  // 0.04, 0.06, 0.08
  EXPECT_EQ(second["points_run"], 1);
  EXPECT_EQ(second["points_resumed"], 2);
  const auto a = by_Lx(first), b = by_Lx(second);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b.at(60000)["cells"], nlohmann::json({64}));  // the depth-averaged run's cells
  EXPECT_FALSE(b.at(60000)["resumed"].get<bool>());
  for (long L : {40000L, 80000L}) {
    // Kept, not re-run: the same numbers, the first run's wall time included.
    EXPECT_TRUE(b.at(L)["resumed"].get<bool>()) << L;
    EXPECT_EQ(b.at(L)["growth_rate"], a.at(L)["growth_rate"]) << L;
    EXPECT_EQ(b.at(L)["wall_seconds"], a.at(L)["wall_seconds"]) << L;
    EXPECT_EQ(b.at(L)["cells"], nlohmann::json({64})) << L;
  }
  // The same file with another grid: refused, not mixed in.
  const auto r = run_granbench("sweep --model depthavg --nx 96 --Lx 0.04:0.08:3 --out " + out,
                               "sweep_refused");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("linear_nx"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  std::filesystem::remove(out);
}

// A point without a growth rate says why, in the JSON and under the table: the measurement's
// reason, also where the point was read back from the sweep file.
TEST(SweepCli, APointWithoutAGrowthRateSaysWhy) {
  const std::string out = temp_file("reason.h5");
  std::filesystem::remove(out);
  // 0.05 s is too short for any window: both models measure nothing
  const std::string args =
      "sweep --model both --Lx 0.08:0.08:1 --t-end 0.05 --resolution coarse "
      "--jobs 2 --quiet --out " +
      out;
  const auto r = run_granbench(args + " --json", "sweep_reason");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["points"].size(), 2u);
  for (const auto& p : j["points"]) {
    EXPECT_TRUE(p["growth_rate"].is_null()) << p;
    ASSERT_TRUE(p["growth_reason"].is_string()) << p;
    EXPECT_NE(p["growth_reason"].get<std::string>().find("too short"), std::string::npos) << p;
  }
  const auto table = run_granbench(args, "sweep_reason_table");
  ASSERT_EQ(table.code, 0) << table.err;
  // (read back from the file this time)
  EXPECT_NE(table.out.find("twod at Lx = 0.08 m: growth not measured: too short"),
            std::string::npos)
      << table.out;
  const auto again = run_granbench(args + " --json", "sweep_reason_kept");
  ASSERT_EQ(again.code, 0) << again.err;
  for (const auto& p : nlohmann::json::parse(again.out)["points"]) {
    EXPECT_TRUE(p["resumed"].get<bool>()) << p;
    EXPECT_NE(p["growth_reason"].get<std::string>().find("too short"), std::string::npos) << p;
  }
  std::filesystem::remove(out);
}

TEST(SweepCli, TwoMpiRanksGiveTheSingleProcessResult) {
#ifndef GRANBENCH_MPIEXEC
  GTEST_SKIP() << "granbench was built without MPI";
#else
  if (!std::filesystem::exists(GRANBENCH_MPIEXEC)) GTEST_SKIP() << "no " << GRANBENCH_MPIEXEC;
  const std::string launcher =
      std::string(GRANBENCH_MPIEXEC) + " --allow-run-as-root --oversubscribe -np 2 ";
  const std::string one = temp_file("one.h5"), two = temp_file("two.h5");
  std::filesystem::remove(one);
  std::filesystem::remove(two);
  const auto single = sweep("--Lx 0.04:0.08:4 --out " + one);
  // Two ranks, resumed halfway: the first run covers 0.04 and 0.08 only.
  const auto part = sweep("--Lx 0.04:0.08:2 --out " + two, launcher);
  ASSERT_EQ(part["ranks"], 2);
  const auto multi = sweep("--Lx 0.04:0.08:4 --out " + two, launcher);
  EXPECT_EQ(multi["ranks"], 2);
  EXPECT_EQ(multi["points_resumed"], 2);
  EXPECT_EQ(multi["points_run"], 2);
  const auto a = by_Lx(single), b = by_Lx(multi);
  ASSERT_EQ(a.size(), 4u);
  ASSERT_EQ(b.size(), 4u);
  for (const auto& [L, p] : a) {
    EXPECT_DOUBLE_EQ(b.at(L)["growth_rate"].get<double>(), p["growth_rate"].get<double>()) << L;
    EXPECT_DOUBLE_EQ(b.at(L)["phase_speed"].get<double>(), p["phase_speed"].get<double>()) << L;
  }
  // One complete output file, no part files left beside it.
  EXPECT_TRUE(std::filesystem::exists(two));
  for (int r : {0, 1})
    EXPECT_FALSE(std::filesystem::exists(two + ".rank" + std::to_string(r) + ".h5"));
  std::filesystem::remove(one);
  std::filesystem::remove(two);
#endif
}

}  // namespace

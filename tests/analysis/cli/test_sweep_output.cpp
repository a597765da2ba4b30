// Two sweeps on one --out: the second is refused with exit 2 and a message naming the lock file,
// and the file is left to the first (qa.md: without a lock each rewrote the file without the
// other's points). And an interrupted sweep without --out does not claim that its points are kept
// for a resume (qa.md: `sweep --plot` without --out said so, from a scratch file it then removed).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "common/output_lock.hpp"
#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::run_granbench;
namespace fs = std::filesystem;

using granbench::testing::ScratchDir;

TEST(SweepOutput, ASecondWriterOfTheSameOutIsRefusedNamingTheLock) {
  const ScratchDir scratch("gb_sweep_lock");
  const fs::path& dir = scratch.path();
  const std::string out = (dir / "sweep.h5").string();
  {
    // This process stands for the first sweep: it holds the output as a running sweep does.
    const granbench::OutputLock first(out);
    const auto second = run_granbench(
        "sweep --model depthavg --nx 64 --jobs 1 --Lx 0.08:0.08:1 --json --out " + out,
        "sweep_lock");
    EXPECT_EQ(second.code, 2) << second.err;
    EXPECT_NE(second.err.find(out + ".lock"), std::string::npos) << second.err;
    EXPECT_EQ(second.err.find('\n'), second.err.size() - 1) << "one line: " << second.err;
    EXPECT_FALSE(fs::exists(out)) << "the refused sweep wrote the file";
  }
  // Released: the same command now runs, and leaves no lock file behind.
  const auto again = run_granbench(
      "sweep --model depthavg --nx 64 --jobs 1 --Lx 0.08:0.08:1 --json --out " + out, "sweep_lock");
  EXPECT_EQ(again.code, 0) << again.err;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out + ".lock"));
}

// An --out that cannot be written is refused before any point runs, with the OS's reason
// (qa.md SW29: the whole sweep ran, then exit 1 naming an internal .partial file).
TEST(SweepOutput, AnOutThatCannotBeWrittenIsRefusedFirst) {
  const std::string out = "/nonexistent_granbench_dir/d/x.h5";
  const auto r = run_granbench(
      "sweep --model depthavg --nx 64 --jobs 1 --Lx 0.08:0.08:1 --quiet "
      "--out " +
          out,
      "sweep_noout");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("granbench: error: --out: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

TEST(SweepOutput, AnInterruptedSweepWithPlotButNoOutDoesNotClaimToKeepItsPoints) {
  const ScratchDir scratch("gb_sweep_int");
  const fs::path& dir = scratch.path();
  // A 2D point of 60 s of flow takes minutes: the SIGINT after 3 s arrives mid-point.
  const auto r = run_granbench(
      "sweep --model twod --resolution coarse --Lx 0.08:0.08:1 --t-end 60"
      " --jobs 1 --quiet --plot sweep.png",
      "sweep_int", "cd " + dir.string() + " && timeout --preserve-status -s INT 3 ");
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("run the same command again"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("kept in"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nothing is kept"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "sweep.png.data.h5")) << "the scratch file of the figure was left";
}

}  // namespace

namespace {

// SIGTERM (a scheduler's or `timeout`'s stop) ends a sweep like Ctrl-C, with exit 143: before,
// only SIGINT was caught and SIGTERM killed the process.
TEST(SweepOutput, SigtermStopsASweepLikeCtrlCWithExit143) {
  const ScratchDir scratch("gb_sweep_term");
  const fs::path& dir = scratch.path();
  const auto r = run_granbench(
      "sweep --model twod --resolution coarse --Lx 0.08:0.08:1 --t-end 60"
      " --jobs 1 --quiet --plot sweep.png",
      "sweep_term", "cd " + dir.string() + " && timeout --preserve-status -s TERM 3 ");
  EXPECT_EQ(r.code, 143) << r.err;
  EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
}

}  // namespace

namespace {

// A run (either model) and compare claim their --out too: a second process writing the same
// file while the first runs is refused with exit 2 naming the lock (issue: "a second process
// writing the same sweep (or run) output is refused").
TEST(SweepOutput, ASecondRunOnTheSameOutIsRefusedNamingTheLock) {
  const ScratchDir scratch("gb_run_lock");
  const fs::path& dir = scratch.path();
  const std::string out = (dir / "run.h5").string();
  const std::string pidfile = (dir / "pid").string();
  const std::string first =
      std::string(GRANBENCH_BINARY_DIR) +
      "/granbench run --model twod --nx 64 --nz 16 --t-end 60 --quiet --out " + out +
      " >/dev/null 2>&1 & echo $! > " + pidfile;
  ASSERT_EQ(std::system(first.c_str()), 0);
  // Stopped when the test ends, also when an ASSERT below returns early (before the directory
  // holding its pid file goes).
  struct StopFirstRun {
    std::string pidfile;
    ~StopFirstRun() {
      std::system(("kill -TERM $(cat " + pidfile + ") 2>/dev/null; sleep 1").c_str());
    }
  } stop_first{pidfile};
  for (int i = 0; i < 100 && !fs::exists(out + ".lock"); ++i) usleep(100000);
  ASSERT_TRUE(fs::exists(out + ".lock")) << "the first run took no lock";
  for (const std::string model : {"twod", "depthavg"}) {
    const auto r =
        run_granbench("run --model " + model + " --t-end 0.1 --quiet --out " + out, "run_lock");
    EXPECT_EQ(r.code, 2) << model << ": " << r.err;
    EXPECT_NE(r.err.find(out + ".lock"), std::string::npos) << r.err;
  }
}

}  // namespace

// Two sweeps on one --out: the second is refused with exit 2 and a message naming the lock file,
// and the file is left to the first (qa.md: without a lock each rewrote the file without the
// other's points). And an interrupted sweep without --out does not claim that its points are kept
// for a resume (qa.md: `sweep --plot` without --out said so, from a scratch file it then removed).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "common/output_lock.hpp"
#include "tests/support/run_granbench.hpp"

namespace {

using granbench::testing::run_granbench;
namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("gb_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(SweepOutput, ASecondWriterOfTheSameOutIsRefusedNamingTheLock) {
  const fs::path dir = temp_dir("sweep_lock");
  const std::string out = (dir / "sweep.h5").string();
  {
    // This process stands for the first sweep: it holds the output as a running sweep does.
    const granbench::OutputLock first(out);
    const auto second = run_granbench(
        "sweep --model depthavg --nx 64 --jobs 1 --Lx 0.08:0.08:1 --json --out " + out,
        "sweep_lock_" + std::to_string(getpid()));
    EXPECT_EQ(second.code, 2) << second.err;
    EXPECT_NE(second.err.find(out + ".lock"), std::string::npos) << second.err;
    EXPECT_EQ(second.err.find('\n'), second.err.size() - 1) << "one line: " << second.err;
    EXPECT_FALSE(fs::exists(out)) << "the refused sweep wrote the file";
  }
  // Released: the same command now runs, and leaves no lock file behind.
  const auto again =
      run_granbench("sweep --model depthavg --nx 64 --jobs 1 --Lx 0.08:0.08:1 --json --out " + out,
                    "sweep_lock_" + std::to_string(getpid()));
  EXPECT_EQ(again.code, 0) << again.err;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out + ".lock"));
  fs::remove_all(dir);
}

// An --out that cannot be written is refused before any point runs, with the OS's reason
// (qa.md SW29: the whole sweep ran, then exit 1 naming an internal .partial file).
TEST(SweepOutput, AnOutThatCannotBeWrittenIsRefusedFirst) {
  const std::string out = "/nonexistent_granbench_dir/d/x.h5";
  const auto r = run_granbench(
      "sweep --model depthavg --nx 64 --jobs 1 --Lx 0.08:0.08:1 --quiet "
      "--out " +
          out,
      "sweep_noout_" + std::to_string(getpid()));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("granbench: error: --out: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

TEST(SweepOutput, AnInterruptedSweepWithPlotButNoOutDoesNotClaimToKeepItsPoints) {
  const fs::path dir = temp_dir("sweep_int");
  // A 2D point of 60 s of flow takes minutes: the SIGINT after 3 s arrives mid-point.
  const auto r = run_granbench(
      "sweep --model twod --resolution coarse --Lx 0.08:0.08:1 --t-end 60"
      " --jobs 1 --quiet --plot sweep.png",
      "sweep_int_" + std::to_string(getpid()),
      "cd " + dir.string() + " && timeout --preserve-status -s INT 3 ");
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("run the same command again"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("kept in"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nothing is kept"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "sweep.png.data.h5")) << "the scratch file of the figure was left";
  fs::remove_all(dir);
}

}  // namespace

namespace {

// SIGTERM (a scheduler's or `timeout`'s stop) ends a sweep like Ctrl-C, with exit 143: before,
// only SIGINT was caught and SIGTERM killed the process.
TEST(SweepOutput, SigtermStopsASweepLikeCtrlCWithExit143) {
  const fs::path dir = temp_dir("sweep_term");
  const auto r = run_granbench(
      "sweep --model twod --resolution coarse --Lx 0.08:0.08:1 --t-end 60"
      " --jobs 1 --quiet --plot sweep.png",
      "sweep_term_" + std::to_string(getpid()),
      "cd " + dir.string() + " && timeout --preserve-status -s TERM 3 ");
  EXPECT_EQ(r.code, 143) << r.err;
  EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

}  // namespace

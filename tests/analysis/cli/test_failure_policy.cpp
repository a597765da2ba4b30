// The failure policy of the run commands end to end (common/failure_policy.hpp, README "Exit
// codes"): paths and record counts checked before any work (exit 2, the option, the OS's reason);
// a failure in the time loop keeps the data (exit 3, status "failed", time and cause); SIGTERM
// keeps what `run --model depthavg`, `compare` and `case` computed (exit 143, status
// "interrupted"); a restart refuses a checkpoint of other physics, naming the option; a steep
// valid flow is not called diverged; compare says n/a where it has no measurement.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "common/hdf5_file.hpp"
#include "common/steady_state.hpp"
#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"
#include "twod/checkpoint.hpp"
#include "twod/initial_state.hpp"
#include "twod/solver.hpp"

namespace {
using granbench::testing::run_granbench;
namespace fs = std::filesystem;

const std::string kTwod = "run --model twod --nx 32 --nz 8 --Lx 0.04 --quiet ";
const std::string kDepthavg = "run --model depthavg --nx 40 --quiet ";
const std::string kCompare = "compare --nx 32 --nz 8 --nx-depthavg 40 --quiet ";

using granbench::testing::ScratchDir;

// A checkpoint at t = 0 of the 32 x 8 run of kTwod with the command line's default physics, the
// velocity optionally poisoned.
void write_default_checkpoint(const std::string& path, bool nan_velocity) {
  using namespace granbench;
  twod::SolverParams params;
  params.zeta = degrees_to_radians(28.5);
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, 0.004);
  const twod::Grid grid(32, 8, 0.04, twod::mid_cell_domain_height(0.004, 8));
  twod::Fields f = twod::make_initial_state(
      grid, twod::perturbed_bagnold(steady_state(curve, params.zeta, 0.004), 2e-4, 0.04), params);
  if (nan_velocity) f.u[grid.at(3, 2)] = std::numeric_limits<double>::quiet_NaN();
  const twod::Solver solver(grid, params, f);
  twod::write_checkpoint(path, solver, SurfaceSeries::uniform_grid(0.04, 32, 0.004));
}

}  // namespace

TEST(FailurePolicy, OutputPathsAreCheckedBeforeAnyWork) {
  // Each would compute for minutes before writing: the refusal must come first.
  for (const std::string& cmd :
       {kTwod + "--t-end 600", kDepthavg + "--t-end 600", kCompare + "--t-end 600",
        std::string("sweep --nx 16 --t-end 600 --Lx 0.08:0.08:1 --quiet"),
        // quick ones too: one failure policy for every command (before, exit 1 from HDF5)
        std::string("steady"), std::string("wellposed"), std::string("dispersion --Lx 0.08"),
        std::string("dispersion --theory twod --Lx 0.08")}) {
    const auto r = run_granbench(cmd + " --out /nonexistent-granbench-dir/x.h5", "fp_out");
    EXPECT_EQ(r.code, 2) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("--out: cannot write '/nonexistent-granbench-dir/x.h5': No such file or "
                         "directory"),
              std::string::npos)
        << r.err;
  }
}

TEST(FailurePolicy, AReadOnlyOutputDirectoryIsRefusedWithPermissionDenied) {
  if (geteuid() == 0) GTEST_SKIP() << "root writes anywhere: no 'Permission denied' to test";
  const ScratchDir dir("gb_fp_ro");
  fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
  const auto r = run_granbench(kDepthavg + "--t-end 600 --out " + dir / "x.h5", "fp_ro");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("Permission denied"), std::string::npos) << r.err;
}

TEST(FailurePolicy, AnUnwritableCheckpointIsRefusedBeforeTheRun) {
  const ScratchDir dir("gb_fp_ckpt");
  const auto r = run_granbench(
      kTwod + "--t-end 600 --out " + dir / "x.h5" + " --checkpoint /nonexistent-granbench-dir/c.h5",
      "fp_ckpt");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--checkpoint: cannot write"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.h5"));
}

TEST(FailurePolicy, SampleAndSnapshotCountsAreBounded) {
  struct Case {
    std::string args, option;
  };
  const Case cases[] = {{kDepthavg + "--t-end 1 --dt-out 1e-9", "--dt-out"},
                        {kTwod + "--t-end 1 --dt-out 1e-9", "--dt-out"},
                        {kCompare + "--t-end 1 --dt-out 1e-9", "--dt-out"},
                        {kTwod + "--t-end 1 --dt-snapshot 1e-6", "--dt-snapshot"}};
  for (const auto& c : cases) {
    const auto r = run_granbench(c.args, "fp_caps");
    EXPECT_EQ(r.code, 2) << c.args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("granbench: error: " + c.option + ":", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("valid range ["), std::string::npos) << r.err;
  }
}

TEST(FailurePolicy, AFailureInTheTimeLoopKeepsTheDataAndExitsThree) {
  const ScratchDir dir("gb_fp_fail");
  write_default_checkpoint(dir / "nan.h5", true);
  const auto r = run_granbench(kTwod + "--twod-frame 0 --t-end 0.05 --json --restart " +
                                   dir / "nan.h5" + " --out " + dir / "x.h5",
                               "fp_fail");
  ASSERT_EQ(r.code, 3) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // A NaN in the velocity fails the viscous solve (an exception, not a DivergenceError).
  EXPECT_EQ(j["status"], "failed") << j["message"];
  EXPECT_EQ(j["message"].get<std::string>().rfind("failed at t = 0", 0), 0u) << j["message"];
  ASSERT_TRUE(fs::exists(dir / "x.h5"));
  EXPECT_GE(granbench::read_surface_series(dir / "x.h5", "/surface").nt(), 1u);
}

TEST(FailurePolicy, ARestartRefusesACheckpointOfOtherPhysics) {
  const ScratchDir dir("gb_fp_phys");
  write_default_checkpoint(dir / "c.h5", false);
  const std::string restart = kTwod + "--t-end 0.02 --restart " + dir / "c.h5";
  // The checkpoint's grid is at rest (the lab frame); the default grid moves.
  const std::string lab = " --twod-frame 0";
  struct Case {
    std::string args, option;
  };
  const Case cases[] = {{"--angle 25", "--angle"},  {"--curve jop --angle 28", "--angle"},
                        {"--curve jop", "--curve"}, {"--mu-s 0.3", "--mu-s"},
                        {"--h0 0.0041", "--h0"},    {"--Lz 0.009", "--Lz"},
                        {"", "--twod-frame"}};
  for (const auto& c : cases) {
    const auto r =
        run_granbench(restart + " " + c.args + (c.option == "--twod-frame" ? "" : lab), "fp_phys");
    EXPECT_EQ(r.code, 2) << c.args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("granbench: error: " + c.option + ": the checkpoint has", 0), 0u)
        << r.err;
  }
  const auto same = run_granbench(restart + lab, "fp_phys_same");
  EXPECT_EQ(same.code, 0) << same.err;
}

TEST(FailurePolicy, SigtermKeepsWhatDepthavgComputed) {
  const ScratchDir dir("gb_fp_term_d");
  // 600 s of flow takes minutes: the SIGTERM after 3 s always arrives mid-run.
  const auto r = run_granbench(
      "run --model depthavg --nx 512 --quiet --json --t-end 600 --out " + dir / "d.h5", "fp_term_d",
      "timeout --preserve-status -s TERM 3 ");
  ASSERT_EQ(r.code, 143) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // printed: the process handled the signal
  EXPECT_EQ(j["status"], "interrupted");
  EXPECT_TRUE(fs::exists(dir / "d.h5"));
}

TEST(FailurePolicy, SigtermKeepsWhatCompareComputed) {
  const ScratchDir dir("gb_fp_term_c");
  const auto r = run_granbench(
      kCompare + "--json --t-end 600 --out " + dir / "c.h5" + " --plot " + dir / "c.png",
      "fp_term_c", "timeout --preserve-status -s TERM 3 ");
  ASSERT_EQ(r.code, 143) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["twod"]["completed"].get<bool>());
  EXPECT_TRUE(fs::exists(dir / "c.h5"));
}

TEST(FailurePolicy, SigtermStopsACaseInThisProcessAndKeepsItsRun) {
  const ScratchDir dir("gb_fp_term_case");
  std::ofstream(dir / "long.toml") << "kind = \"rollwave\"\nprobe_x = 0.01\n"
                                      "[run]\nnx = 32\nnz = 8\nLx = 0.04\nt-end = 600.0\n"
                                      "[smoke]\nprobe_window = [0.1, 0.2]\nfield_time = 0.2\n";
  const auto r = run_granbench("case long --resolution smoke --quiet --json --cases-dir " +
                                   dir.str() + " --out-dir " + dir.str(),
                               "fp_term_case", "timeout --preserve-status -s TERM 3 ");
  ASSERT_EQ(r.code, 143) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["run"]["status"], "interrupted");
  EXPECT_TRUE(fs::exists(dir / "long.h5"));
  EXPECT_TRUE(fs::exists(dir / "long.checkpoint.h5"));
}

TEST(FailurePolicy, ASteepValidFlowIsNotCalledDivergedAtItsFirstStep) {
  // Regularised curve at 60 degrees: the surface moves at 47.7 m/s, near the former fixed
  // 50 m/s divergence limit.
  const auto r = run_granbench(kTwod + "--angle 60 --t-end 0.005 --json", "fp_steep");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "completed");
}

TEST(FailurePolicy, CompareSaysNotAvailableWhereThereIsNoMeasurement) {
  const ScratchDir dir("gb_fp_na");
  const std::string cmd =
      kCompare + "--t-end 0.05 --dt-out 1 --out " + dir / "c.h5" + " --plot " + dir / "c.png";
  const auto text = run_granbench(cmd, "fp_na");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("n/a"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("-100"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("ln|h_k| 0.000"), std::string::npos) << text.out;
  const auto j = nlohmann::json::parse(run_granbench(cmd + " --json", "fp_na_json").out);
  for (const char* model : {"depthavg", "twod"}) {
    EXPECT_TRUE(j[model]["growth_rate"].is_null()) << model;
    EXPECT_TRUE(j[model]["growth_rate_whole_run"].is_null()) << model;
  }
}

TEST(FailurePolicy, EveryExitCodeIsInTheHelpOfTheRunCommands) {
  for (const char* cmd : {"run --help", "compare --help", "case --help"}) {
    const auto r = run_granbench(cmd, "fp_help");
    EXPECT_EQ(r.code, 0) << cmd;
    for (const char* code : {"Exit codes", "  0 ", "  1 ", "  2 ", "  3 ", "  130 ", "  143 "})
      EXPECT_NE(r.out.find(code), std::string::npos) << cmd << ": " << code;
  }
}

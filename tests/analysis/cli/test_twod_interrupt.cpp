// `granbench run --model twod` interrupted with Ctrl-C (SIGINT, sent by `timeout`): it keeps what
// it computed (the output file, not a .partial, and a JSON result with status "interrupted"),
// writes a checkpoint and exits with code 130; `--restart` continues from the checkpoint to the
// end time with the granular volume conserved.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {
using granbench::testing::run_granbench;
namespace fs = std::filesystem;
using granbench::testing::ScratchDir;

// (the linear solves to 1e-12, not the default 1e-10: the bound at the end)
const std::string kRun =
    "run --model twod --nx 64 --nz 16 --Lx 0.08 --json --quiet --tolerance 1e-12 ";
}  // namespace

TEST(TwoDInterrupt, CtrlCKeepsTheOutputWritesACheckpointAndTheRunRestarts) {
  const ScratchDir scratch("gb_twod_int");
  const fs::path& dir = scratch.path();
  const std::string out = (dir / "run.h5").string(), checkpoint = (dir / "run.ckpt.h5").string();

  // 60 s of flow would take minutes: the SIGINT after 3 s always arrives mid-run.
  const auto first = run_granbench(kRun + "--t-end 60 --out " + out + " --checkpoint " + checkpoint,
                                   "twod_int", "timeout --preserve-status -s INT 3 ");
  ASSERT_EQ(first.code, 130) << first.err;
  EXPECT_NE(first.err.find("interrupted at t ="), std::string::npos) << first.err;
  const auto j = nlohmann::json::parse(first.out);
  EXPECT_EQ(j["status"], "interrupted");
  const double t_stop = j["t_reached"].get<double>();
  EXPECT_GT(t_stop, 0.0);
  EXPECT_LT(t_stop, 60.0);
  EXPECT_TRUE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out + ".partial"));
  ASSERT_TRUE(fs::exists(checkpoint));

  const double t_end = std::ceil((t_stop + 0.05) * 1000.0) / 1000.0;  // exact in to_string
  const auto second = run_granbench(kRun + "--t-end " + std::to_string(t_end) + " --restart " +
                                        checkpoint + " --out " + (dir / "rest.h5").string(),
                                    "twod_rest");
  ASSERT_EQ(second.code, 0) << second.err;
  const auto k = nlohmann::json::parse(second.out);
  EXPECT_EQ(k["status"], "completed");
  EXPECT_NEAR(k["t_reached"].get<double>(), t_end, 1e-9);
  EXPECT_GT(k["steps"].get<long>(), j["steps"].get<long>());  // counted from the first run on
  // The granular volume moves with the projection's residual divergence (the VOF step conserves
  // it to round-off only in a divergence-free velocity), so the run solves to 1e-12. At the
  // default 1e-10 this steep sine start on 8 cells per h0 reached mass errors of 2.2e-11 (at 5 s)
  // and 7.2e-11 (at 6 s, after the consistent transport's upwinding by the mass flux, 51st
  // session), so the check depended on where the interrupt landed; at 1e-12 the error stays
  // within 5.2e-13 over the first 8 s (both codes, at 3, 5, 6 and 8 s). A restart that lost or
  // doubled one cell would be off by 2e-3.
  EXPECT_LT(std::abs(k["mass_error"].get<double>()), 5e-12);
}

// twod::run's checkpoint schedule, last snapshot and failure capture (twod/run.hpp), and the
// checkpoint's physics (twod/checkpoint.hpp): checkpoints on the dt_checkpoint grid do not change
// the run; the output ends with a snapshot at t_end also off the snapshot grid; an exception in
// the loop keeps the samples with time and cause; a checkpoint that cannot be written at a stop
// keeps the run; a restart with other physics is named by the parameter that differs.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/steady_state.hpp"
#include "tests/support/scratch_dir.hpp"
#include "tests/support/small_twod_rollwave.hpp"
#include "twod/checkpoint.hpp"
#include "twod/initial_state.hpp"
#include "twod/run.hpp"
#include "twod/solver.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {

using Case = granbench::testing::SmallTwodRollwave;

RunSchedule schedule(double t_end, double dt_out, double dt_snapshot, double dt_checkpoint) {
  RunSchedule s;
  s.t_end = t_end;
  s.dt_out = dt_out;
  s.dt_snapshot = dt_snapshot;
  s.dt_checkpoint = dt_checkpoint;
  return s;
}

}  // namespace

TEST(TwodRunOutput, CheckpointsOnTheirGridLeaveTheRunUnchanged) {
  const Case c;
  Solver a = c.solver();
  const RunResult plain = run(a, c.empty_series(), schedule(0.05, 0.01, 0.0, 0.0));
  std::vector<double> at;
  RunHooks hooks;
  hooks.checkpoint = [&](const Solver& s, const SurfaceSeries&) { at.push_back(s.state().t); };
  Solver b = c.solver();
  // 0.015 is off the sample grid: each checkpoint waits for the first sample at or after its
  // time (0.015 -> 0.02, 0.03 -> 0.03, 0.045 -> 0.05, which is t_end: none there).
  const RunResult checked = run(b, c.empty_series(), schedule(0.05, 0.01, 0.0, 0.015), hooks);
  ASSERT_TRUE(checked.completed()) << checked.message;
  ASSERT_EQ(at.size(), 2u);
  EXPECT_NEAR(at[0], 0.02, 1e-15);
  EXPECT_NEAR(at[1], 0.03, 1e-15);
  EXPECT_EQ(checked.series.h, plain.series.h);
  EXPECT_EQ(b.statistics().steps, a.statistics().steps);
}

TEST(TwodRunOutput, TheLastSnapshotIsAtTEndAlsoOffTheSnapshotGrid) {
  const Case c;
  Solver solver = c.solver();
  std::vector<double> snapshots;
  RunHooks hooks;
  hooks.snapshot = [&](const Solver& s) { snapshots.push_back(s.state().t); };
  const RunResult r = run(solver, c.empty_series(), schedule(0.05, 0.01, 0.02, 0.0), hooks);
  ASSERT_TRUE(r.completed()) << r.message;
  const std::vector<double> expected = {0.0, 0.02, 0.04, 0.05};
  ASSERT_EQ(snapshots.size(), expected.size());
  for (std::size_t n = 0; n < expected.size(); ++n) EXPECT_NEAR(snapshots[n], expected[n], 1e-15);
}

TEST(TwodRunOutput, AnExceptionInTheLoopKeepsTheSamplesWithTimeAndCause) {
  const Case c;
  Solver solver = c.solver();
  RunHooks hooks;
  hooks.sample = [](const Solver& s, const SurfaceSeries&) {
    if (s.state().t > 0.025) throw std::runtime_error("no space left on device");
  };
  const RunResult r = run(solver, c.empty_series(), schedule(0.05, 0.01, 0.0, 0.0), hooks);
  EXPECT_EQ(r.status, RunStatus::Failed);
  EXPECT_EQ(r.series.nt(), 4u);  // 0 .. 0.03: the failing sample was appended before its hook
  EXPECT_NE(r.message.find("failed at t = 0.03"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("no space left on device"), std::string::npos) << r.message;
}

TEST(TwodRunOutput, AnUnwritableCheckpointAtAStopKeepsTheRun) {
  const Case c;
  Solver solver = c.solver();
  std::atomic<bool> stop{true};
  RunHooks hooks;
  hooks.stop = &stop;
  hooks.checkpoint = [](const Solver& s, const SurfaceSeries& kept) {
    write_checkpoint("/nonexistent-granbench-dir/c.h5", s, kept);
  };
  RunResult r;
  ASSERT_NO_THROW(r = run(solver, c.empty_series(), schedule(0.05, 0.01, 0.0, 0.0), hooks));
  EXPECT_EQ(r.status, RunStatus::Interrupted);
  EXPECT_EQ(r.series.nt(), 1u);
  EXPECT_NE(r.message.find("no checkpoint"), std::string::npos) << r.message;
}

TEST(TwodRunOutput, ARestartWithOtherPhysicsNamesTheParameter) {
  const Case c;
  const Solver solver = c.solver();
  const granbench::testing::ScratchDir dir("gb_physics_checkpoint");
  const std::string path = dir / "checkpoint.h5";
  write_checkpoint(path, solver, c.empty_series(), {0.0, 0.5});
  const Checkpoint cp = read_checkpoint(path);
  EXPECT_EQ(cp.snapshot_times, (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(restart_mismatch(cp, c.grid, c.params), "");

  SolverParams p = c.params;
  p.zeta = degrees_to_radians(25.0);
  EXPECT_EQ(restart_mismatch(cp, c.grid, p).rfind("angle: the checkpoint has 28.5", 0), 0u);
  p = c.params;
  p.rheology.curve = CurveKind::Jop;
  EXPECT_EQ(restart_mismatch(cp, c.grid, p), "curve: the checkpoint has regularised, this run jop");
  p = c.params;
  p.rheology.material.mu_s = 0.3;
  EXPECT_EQ(restart_mismatch(cp, c.grid, p).rfind("mu-s:", 0), 0u);
  p = c.params;
  p.rheology.h0_for_curve = 0.005;
  EXPECT_EQ(restart_mismatch(cp, Grid(32, 8, 0.04, 0.01), p).rfind("h0:", 0), 0u);
  EXPECT_EQ(restart_mismatch(cp, Grid(40, 8, 0.04, 0.008), c.params).rfind("nx:", 0), 0u);
  p = c.params;
  p.rheology.effective_pressure = !p.rheology.effective_pressure;
  EXPECT_EQ(restart_mismatch(cp, c.grid, p).rfind("effective-pressure:", 0), 0u);
  // a checkpoint written before the effective pressure was recorded (its physics without it)
  Checkpoint older = cp;
  std::erase_if(older.physics, [](const auto& e) { return e.first == "effective-pressure"; });
  EXPECT_EQ(restart_mismatch(older, c.grid, c.params),
            "effective-pressure: not recorded in the checkpoint (written by an older granbench)");
}

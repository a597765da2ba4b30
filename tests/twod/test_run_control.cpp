// Run control of the 2D solver: a runaway velocity is reported as a DivergenceError naming the
// time, place and quantity; a checkpoint written mid-run restores the state exactly and the
// restarted run continues identically to the uninterrupted one. twod::run (twod/run.hpp): the
// samples lie on the uniform grid k dt_out from t = 0 (the last on t_end), snapshots on
// j dt_snapshot; a raised stop flag ends the run at the next sample with the series so far and
// calls the checkpoint hook; a run restarted from that checkpoint continues the same sample grid
// and repeats the uninterrupted run bit for bit.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "common/steady_state.hpp"
#include "tests/support/scratch_dir.hpp"
#include "tests/support/small_twod_rollwave.hpp"
#include "twod/checkpoint.hpp"
#include "twod/initial_state.hpp"
#include "twod/run.hpp"
#include "twod/solver.hpp"
#include "twod/time_step.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {
using Case = granbench::testing::SmallTwodRollwave;

RunSchedule schedule(double t_end, double dt_out, double dt_snapshot = 0.0) {
  RunSchedule s;
  s.t_end = t_end;
  s.dt_out = dt_out;
  s.dt_snapshot = dt_snapshot;
  return s;
}

}  // namespace

TEST(RunControl, RunawayVelocityIsReportedWithTimeAndPlace) {
  Case c;
  c.params.velocity_limit = 0.5;  // the surface moves at ~1 m/s: "runaway" at once
  Solver solver(c.grid, c.params, make_initial_state(c.grid, c.ic, c.params));
  try {
    solver.step(1.0);
    FAIL() << "no DivergenceError";
  } catch (const DivergenceError& e) {
    EXPECT_GT(e.t, 0.0);
    EXPECT_GE(e.x, 0.0);
    EXPECT_LE(e.x, c.grid.Lx);
    EXPECT_GT(e.z, 0.0);
    EXPECT_NE(std::string(e.what()).find("diverged at t ="), std::string::npos);
  }
}

namespace {
// A scratch file of this test process (ctest runs each test in its own process, two at a time:
// the two restart tests writing one fixed name made each other fail now and then).
std::string scratch_path(const std::string& stem) {
  static const granbench::testing::ScratchDir dir("gb_twod_run_control");
  return dir / (stem + ".h5");
}

void expect_restart_continues_identically(const Case& c) {
  Solver a(c.grid, c.params, make_initial_state(c.grid, c.ic, c.params));
  a.advance_to(0.01);
  const std::string path = scratch_path("granbench_twod_checkpoint_test");
  SurfaceSeries series = SurfaceSeries::uniform_grid(c.grid.Lx, c.grid.nx, 0.004);
  write_checkpoint(path, a, series);
  const Checkpoint cp = read_checkpoint(path);
  std::filesystem::remove(path);
  EXPECT_EQ(cp.state.u, a.state().u);
  EXPECT_EQ(cp.state.f, a.state().f);
  EXPECT_EQ(cp.state.t, a.state().t);
  Solver b(cp.grid, c.params, cp.state);
  b.resume(cp.steps, cp.dt_last, cp.initial_volume);
  b.set_warm_start(cp.warm_start);
  a.advance_to(0.02);
  b.advance_to(0.02);
  EXPECT_EQ(a.statistics().steps, b.statistics().steps);
  // The checkpoint holds the solvers' initial guesses too, so the runs agree bit for bit.
  EXPECT_EQ(a.state().u, b.state().u);
  EXPECT_EQ(a.state().w, b.state().w);
  EXPECT_EQ(a.state().p, b.state().p);
  EXPECT_EQ(a.state().f, b.state().f);
}
}  // namespace

TEST(RunControl, CheckpointRestartContinuesIdentically) {
  expect_restart_continues_identically(Case{});
}

// The option that moves the interface with the mid-step velocity keeps u^{n-1} in the checkpoint.
TEST(RunControl, CheckpointRestartContinuesIdenticallyWithTheMidStepInterfaceVelocity) {
  Case c;
  c.params.interface_midstep_velocity = true;
  expect_restart_continues_identically(c);
}

// The first step is the CFL step of the initial state: a seeded run starts from the steady flow,
// whose CFL step holds at once (the 1e-5 s start grown by 10 % a step took 27 extra steps of the
// Gerris comparison's 320; docs/performance.md). dt_initial, when set, caps the first step.
TEST(RunControl, TheFirstStepIsTheCflStepUnlessCapped) {
  Case c;
  ASSERT_EQ(c.params.dt_initial, 0.0);  // the default: no cap
  Solver solver(c.grid, c.params, make_initial_state(c.grid, c.ic, c.params));
  const double cfl_step = choose_time_step(c.grid, solver.state(), c.params, 0.0);
  ASSERT_LT(cfl_step, c.params.dt_max);  // the flow's CFL limit, not dt_max, sets it
  EXPECT_EQ(solver.step(1.0), cfl_step);
  c.params.dt_initial = 0.25 * cfl_step;
  Solver capped(c.grid, c.params, make_initial_state(c.grid, c.ic, c.params));
  EXPECT_EQ(capped.step(1.0), 0.25 * cfl_step);
  EXPECT_LE(capped.step(1.0), c.params.dt_growth * 0.25 * cfl_step);  // then grows from there
}

// Output times every 3.3 steps or so: the step before each output time is never a sliver. The
// solver takes the remainder when it is at most one step and two equal halves when it is
// between one and two steps, so no step is shorter than half the CFL step (a 1e-8 s step
// divides the solvers' residuals by 1e-8 s in the projection: docs/twod-validation.md).
TEST(RunControl, NoSliverStepsBeforeOutputTimes) {
  Case c;
  Solver solver(c.grid, c.params, make_initial_state(c.grid, c.ic, c.params));
  solver.advance_to(0.02);  // past the first steps
  const double dt_cfl = solver.step(1.0);
  double shortest = dt_cfl;
  int steps = 0;
  for (int n = 1; n <= 60; ++n) {
    const double target = 0.02 + dt_cfl + n * 3.3 * dt_cfl;
    while (solver.state().t < target * (1.0 - 1e-14)) {
      shortest = std::min(shortest, solver.step(target - solver.state().t));
      ++steps;
    }
    EXPECT_DOUBLE_EQ(solver.state().t, target);
  }
  std::printf("%d steps to 60 output times 3.3 steps apart: shortest %.3g of the CFL step\n", steps,
              shortest / dt_cfl);
  EXPECT_GT(shortest, 0.45 * dt_cfl);
}

TEST(TwodRun, SamplesAndSnapshotsLieOnTheirUniformGrids) {
  const Case c;
  Solver solver = c.solver();
  std::vector<double> snapshots;
  int samples_seen = 0;
  RunHooks hooks;
  hooks.snapshot = [&](const Solver& s) { snapshots.push_back(s.state().t); };
  hooks.sample = [&](const Solver&, const SurfaceSeries&) { ++samples_seen; };
  // t_end is not a multiple of dt_out: the last sample is at t_end (as in depthavg's run).
  const RunResult r = run(solver, c.empty_series(), schedule(0.045, 0.01, 0.015), hooks);
  ASSERT_TRUE(r.completed()) << r.message;
  const std::vector<double> expected = {0.0, 0.01, 0.02, 0.03, 0.04, 0.045};
  ASSERT_EQ(r.series.nt(), expected.size());
  for (std::size_t n = 0; n < expected.size(); ++n) EXPECT_NEAR(r.series.t[n], expected[n], 1e-15);
  EXPECT_EQ(samples_seen, 6);
  const std::vector<double> snap_expected = {0.0, 0.015, 0.03, 0.045};
  ASSERT_EQ(snapshots.size(), snap_expected.size());
  for (std::size_t n = 0; n < snapshots.size(); ++n)
    EXPECT_NEAR(snapshots[n], snap_expected[n], 1e-15);
  EXPECT_EQ(r.series.u_mean.size(), r.series.h.size());  // depth-averaged velocity sampled too
  EXPECT_GT(r.I_max, r.I_min);
  EXPECT_DOUBLE_EQ(solver.state().t, 0.045);
}

TEST(TwodRun, StopFlagEndsTheRunAtTheNextSampleAndRestartContinuesTheGrid) {
  const Case c;
  const RunSchedule sched = schedule(0.05, 0.01, 0.025);
  RunHooks record_snapshots;
  record_snapshots.snapshot = [](const Solver&) {};

  // The uninterrupted run.
  Solver a = c.solver();
  const RunResult full = run(a, c.empty_series(), sched, record_snapshots);
  ASSERT_TRUE(full.completed()) << full.message;
  ASSERT_EQ(full.series.nt(), 6u);

  // The flag is raised between samples (at the snapshot at 0.025 s): the run goes on to the
  // sample at 0.03 s and stops there.
  const std::string path = scratch_path("granbench_twod_run_test");
  std::atomic<bool> stop{false};
  int checkpoints = 0;
  RunHooks hooks;
  hooks.stop = &stop;
  hooks.snapshot = [&](const Solver& s) {
    if (s.state().t > 0.02) stop.store(true);
  };
  hooks.checkpoint = [&](const Solver& s, const SurfaceSeries& kept) {
    ++checkpoints;
    write_checkpoint(path, s, kept);
  };
  Solver b = c.solver();
  const RunResult first = run(b, c.empty_series(), sched, hooks);
  EXPECT_EQ(first.status, RunStatus::Interrupted);
  EXPECT_NE(first.message.find("interrupted at t ="), std::string::npos);
  EXPECT_EQ(checkpoints, 1);
  ASSERT_EQ(first.series.nt(), 4u);
  EXPECT_DOUBLE_EQ(b.state().t, 0.03);
  EXPECT_EQ(first.series.h,
            std::vector<double>(full.series.h.begin(), full.series.h.begin() + 4 * c.grid.nx));

  // The restart from the checkpoint samples at 0.04 and 0.05, not 0.03 + k dt_out, and ends
  // where the uninterrupted run ended, to the bit.
  const Checkpoint cp = read_checkpoint(path);
  std::filesystem::remove(path);
  Solver d(cp.grid, c.params, cp.state);
  d.resume(cp.steps, cp.dt_last, cp.initial_volume);
  d.set_warm_start(cp.warm_start);
  const RunResult rest = run(d, cp.series, sched, record_snapshots);
  ASSERT_TRUE(rest.completed()) << rest.message;
  EXPECT_EQ(rest.series.t, full.series.t);
  EXPECT_EQ(rest.series.h, full.series.h);
  EXPECT_EQ(d.statistics().steps, a.statistics().steps);
  EXPECT_EQ(d.state().u, a.state().u);
}

TEST(TwodRun, DivergenceIsReportedWithTheSamplesSoFar) {
  Case c;
  c.params.velocity_limit = 0.5;  // the surface moves at ~1 m/s: "runaway" in the first step
  Solver solver = c.solver();
  const RunResult r = run(solver, c.empty_series(), schedule(0.05, 0.01));
  EXPECT_EQ(r.status, RunStatus::Diverged);
  ASSERT_TRUE(r.divergence.has_value());
  EXPECT_GT(r.divergence->t, 0.0);
  EXPECT_EQ(r.series.nt(), 1u);  // the initial state
  EXPECT_FALSE(r.message.empty());
}

// A run that stops early ends with a snapshot of its last state: after an interruption's
// checkpoint (so the checkpoint's snapshot list, which a restart carries over, does not hold it),
// and after a divergence.
TEST(TwodRun, AStoppedOrDivergedRunEndsWithASnapshotOfItsLastState) {
  Case c;
  std::atomic<bool> stop{false};
  std::vector<double> snapshot_times;
  int checkpoints = 0, checkpoints_before_last_snapshot = -1;
  RunHooks hooks;
  hooks.stop = &stop;
  hooks.snapshot = [&](const Solver& s) {
    snapshot_times.push_back(s.state().t);
    checkpoints_before_last_snapshot = checkpoints;
    if (s.state().t > 0.02) stop.store(true);
  };
  hooks.checkpoint = [&](const Solver&, const SurfaceSeries&) { ++checkpoints; };
  Solver b = c.solver();
  const RunResult stopped = run(b, c.empty_series(), schedule(0.05, 0.01, 0.025), hooks);
  ASSERT_EQ(stopped.status, RunStatus::Interrupted);
  EXPECT_EQ(snapshot_times, (std::vector<double>{0.0, 0.025, b.state().t}));
  EXPECT_DOUBLE_EQ(b.state().t, 0.03);
  EXPECT_EQ(checkpoints_before_last_snapshot, 1);

  c.params.velocity_limit = 0.5;  // "runaway" in the first step
  snapshot_times.clear();
  RunHooks record;
  record.snapshot = [&](const Solver& s) { snapshot_times.push_back(s.state().t); };
  Solver d = c.solver();
  const RunResult diverged = run(d, c.empty_series(), schedule(0.05, 0.01, 0.025), record);
  ASSERT_EQ(diverged.status, RunStatus::Diverged);
  ASSERT_FALSE(snapshot_times.empty());
  EXPECT_EQ(snapshot_times.back(), d.state().t);
}

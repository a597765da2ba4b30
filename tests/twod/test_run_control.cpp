// Run control of the 2D solver: a runaway velocity is reported as a DivergenceError naming the
// time, place and quantity; a checkpoint written mid-run restores the state exactly and the
// restarted run continues identically to the uninterrupted one.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "checkpoint.hpp"
#include "initial_state.hpp"
#include "solver.hpp"
#include "steady_state.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {
struct Case {
  SolverParams params;
  Grid grid{32, 8, 0.04, 0.008};
  InitialCondition ic;
  Case() {
    params.zeta = degrees_to_radians(28.5);
    const MuCurve curve(CurveKind::Regularised, params.rheology.material, 0.004);
    ic = perturbed_bagnold(steady_state(curve, params.zeta, 0.004), 2e-4, grid.Lx);
  }
};
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

TEST(RunControl, CheckpointRestartContinuesIdentically) {
  Case c;
  Solver a(c.grid, c.params, make_initial_state(c.grid, c.ic, c.params));
  a.advance_to(0.01);
  const std::string path =
      (std::filesystem::temp_directory_path() / "granbench_twod_checkpoint_test.h5").string();
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

// Output times every 3.3 steps or so: the step before each output time is never a sliver. The
// solver takes the remainder when it is at most one step and two equal halves when it is
// between one and two steps, so no step is shorter than half the CFL step (a 1e-8 s step
// divides the solvers' residuals by 1e-8 s in the projection: docs/twod-validation.md).
TEST(RunControl, NoSliverStepsBeforeOutputTimes) {
  Case c;
  Solver solver(c.grid, c.params, make_initial_state(c.grid, c.ic, c.params));
  solver.advance_to(0.02);  // past the start-up ramp of dt
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

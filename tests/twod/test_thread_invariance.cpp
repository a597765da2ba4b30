// The 2D solver gives bitwise identical results for any number of threads
// (twod/parallel.hpp): the same small nonlinear rollwave run with 1 and with 2 threads must
// produce the same surface series h(x, t), u_mean(x, t) and the same final u, w, p, f, step
// count and solver iterations, to the bit. This fails if any parallel loop lets its result
// depend on the thread count: an `omp reduction` in the conjugate-gradient dot products, a
// Gauss-Seidel line sweep whose lines of one colour read each other, a race between columns.
//
// Two grids: 128 x 32 (even nx; the finest multigrid level is large enough to be threaded) and
// 65 x 32 (odd nx: the zebra colours meet across the periodic boundary, the grid cannot be
// coarsened and the multigrid iterates line sweeps on its only level). Both large enough for
// every threaded path (parallel loops are skipped below 2048 cells in the multigrid). The even
// grid moves at half the surface speed, as the commands' runs do (twod/frame.hpp); the odd one
// is at rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "common/steady_state.hpp"
#include "twod/initial_state.hpp"
#include "twod/parallel.hpp"
#include "twod/run.hpp"
#include "twod/solver.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {

struct Outcome {
  RunResult result;
  Fields state;
  RunStatistics stats;
};

Outcome run_with_threads(int nx, int nz, int threads, double frame_fraction) {
  SolverParams params;
  params.zeta = degrees_to_radians(28.5);
  params.threads = threads;
  const double h0 = 4e-3, Lx = 0.08;
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, h0);
  // a0 = h0/10: the surface crosses cell faces within the run, so the VOF fluxes, the interface
  // pressure and the viscosity jumps all move.
  const SteadyState steady = steady_state(curve, params.zeta, h0);
  const InitialCondition ic = perturbed_bagnold(steady, 4e-4, Lx);
  Grid g(nx, nz, Lx, 2.0 * h0);
  g.frame_speed = frame_fraction * steady.u_surface;
  Solver solver(g, params, make_initial_state(g, ic, params));
  RunSchedule schedule;
  schedule.t_end = 0.008;
  schedule.dt_out = 0.002;
  RunResult r = run(solver, SurfaceSeries::uniform_grid(Lx, std::size_t(nx), h0), schedule);
  return {std::move(r), solver.state(), solver.statistics()};
}

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

void expect_identical(int nx, int nz, double frame_fraction) {
  const Outcome one = run_with_threads(nx, nz, 1, frame_fraction);
  const Outcome two = run_with_threads(nx, nz, 2, frame_fraction);
  ASSERT_EQ(one.result.status, RunStatus::Completed) << one.result.message;
  ASSERT_EQ(two.result.status, RunStatus::Completed) << two.result.message;
  EXPECT_GT(one.stats.steps, 20) << "steps " << one.stats.steps << " viscous it "
                                 << one.stats.viscous_iterations << " pressure it "
                                 << one.stats.projection_iterations;
  EXPECT_EQ(one.stats.steps, two.stats.steps);
  EXPECT_EQ(one.stats.viscous_iterations, two.stats.viscous_iterations);
  EXPECT_EQ(one.stats.projection_iterations, two.stats.projection_iterations);
  EXPECT_TRUE(bitwise_equal(one.result.series.t, two.result.series.t));
  EXPECT_TRUE(bitwise_equal(one.result.series.h, two.result.series.h));
  EXPECT_TRUE(bitwise_equal(one.result.series.u_mean, two.result.series.u_mean));
  EXPECT_TRUE(bitwise_equal(one.state.u, two.state.u));
  EXPECT_TRUE(bitwise_equal(one.state.w, two.state.w));
  EXPECT_TRUE(bitwise_equal(one.state.p, two.state.p));
  EXPECT_TRUE(bitwise_equal(one.state.f, two.state.f));
  // the run moved: the surface changed between the first and the last sample
  const auto& s = one.result.series;
  ASSERT_GE(s.nt(), 2u);
  const std::vector<double> first(s.h_at(0).begin(), s.h_at(0).end());
  const std::vector<double> last(s.h_at(s.nt() - 1).begin(), s.h_at(s.nt() - 1).end());
  EXPECT_FALSE(bitwise_equal(first, last));
}

}  // namespace

TEST(ThreadInvariance, EvenGridOneAndTwoThreadsBitwiseIdentical) {
  expect_identical(128, 32, 0.5);
}

TEST(ThreadInvariance, OddGridOneAndTwoThreadsBitwiseIdentical) {
  expect_identical(65, 32, 0.0);
}

// The Picard passes of the 2D step (SolverParams::viscosity_passes): each further pass takes eta
// from the previous pass's u^{n+1}, p^{n+1}, so the passes are a fixed-point iteration for the
// step with eta at the new level. Over the same steps from the same state, the velocities of
// 1, 2, 3 passes approach those of 5 passes, each closer than the last.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "common/steady_state.hpp"
#include "twod/initial_state.hpp"
#include "twod/solver.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {
std::vector<double> velocity_after(int passes, double a0, int steps) {
  SolverParams params;
  params.zeta = degrees_to_radians(28.5);
  params.viscosity_passes = passes;
  params.dt_initial = 1e-4;
  params.dt_growth = 1.0;  // the same steps for every pass count
  params.dt_max = 1e-4;
  const Grid grid(32, 16, 0.04, 0.008);
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, 0.004);
  const auto ic = perturbed_bagnold(steady_state(curve, params.zeta, 0.004), a0, grid.Lx);
  Solver solver(grid, params, make_initial_state(grid, ic, params));
  for (int n = 0; n < steps; ++n) solver.step(1.0);
  return solver.state().u;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t n = 0; n < a.size(); ++n) d = std::max(d, std::abs(a[n] - b[n]));
  return d;
}
}  // namespace

TEST(ViscosityPasses, FurtherPassesConvergeToTheNewLevelViscosity) {
  const int steps = 20;
  const auto reference = velocity_after(5, 2e-4, steps);
  double previous = std::numeric_limits<double>::infinity();
  for (int passes = 1; passes <= 3; ++passes) {
    const double d = max_difference(velocity_after(passes, 2e-4, steps), reference);
    std::printf("passes %d: max |u - u(5 passes)| = %.3e m/s\n", passes, d);
    EXPECT_LT(d, previous) << passes << " passes";
    previous = d;
  }
  EXPECT_LT(previous, 1e-3);
}

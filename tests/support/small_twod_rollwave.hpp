// A small 2D rollwave for the tests of the run loop, its output and checkpoints: 32 x 8 cells,
// 4 cm x 8 mm, the §7 slope and depth, the paper's sine start (7.2) at a0 = 0.2 mm. A step takes
// about a millisecond, so a test can run it for a few tenths of a second.
#pragma once

#include "common/steady_state.hpp"
#include "common/surface_series.hpp"
#include "twod/initial_state.hpp"
#include "twod/solver.hpp"

namespace granbench::testing {

struct SmallTwodRollwave {
  twod::SolverParams params;
  twod::Grid grid{32, 8, 0.04, 0.008};
  twod::InitialCondition ic;
  SmallTwodRollwave() {
    params.zeta = degrees_to_radians(28.5);
    const MuCurve curve(CurveKind::Regularised, params.rheology.material, 0.004);
    ic = twod::perturbed_bagnold(steady_state(curve, params.zeta, 0.004), 2e-4, grid.Lx);
  }
  twod::Solver solver() const {
    return twod::Solver(grid, params, twod::make_initial_state(grid, ic, params));
  }
  SurfaceSeries empty_series() const {
    return SurfaceSeries::uniform_grid(grid.Lx, grid.nx, 0.004);
  }
};

}  // namespace granbench::testing

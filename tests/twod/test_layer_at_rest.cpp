// (d) A granular layer at rest on a horizontal bed stays at rest: gravity and the pressure
// gradient sit on the same faces with the same densities (balanced force), so the discrete
// hydrostatic state is an exact equilibrium of the full step (VOF, mu(I) viscosity capped at
// eta_max, implicit viscous step, projection). Spurious speeds must stay below 1e-10 m/s, for a
// surface on a cell face and one cutting the cells.
#include <gtest/gtest.h>

#include <cstdio>

#include "twod/diagnostics.hpp"
#include "twod/initial_state.hpp"
#include "twod/solver.hpp"

using namespace granbench::twod;

namespace {
double spurious_speed_after(double h0, int steps) {
  const Grid g(32, 16, 0.02, 0.008);
  SolverParams params;
  params.zeta = 0.0;
  params.dt_max = 1e-3;
  params.dt_initial = 1e-3;
  Solver solver(g, params, make_initial_state(g, layer_at_rest(h0), params));
  double vmax = 0.0;
  for (int n = 0; n < steps; ++n) {
    solver.step(1.0);
    vmax = std::max(vmax, max_speed(solver.state()));
  }
  EXPECT_NEAR(solver.state().t, steps * 1e-3, 1e-12);
  EXPECT_LT(std::abs(solver.statistics().mass_error()), 1e-14);
  std::printf("layer at rest (h0 = %g m): largest speed over %d steps %.3e m/s, mass error %.3e\n",
              h0, steps, vmax, solver.statistics().mass_error());
  return vmax;
}
}  // namespace

TEST(LayerAtRest, SurfaceOnCellFace) {
  EXPECT_LT(spurious_speed_after(0.004, 300), 1e-10);
}

TEST(LayerAtRest, SurfaceInsideCells) {
  EXPECT_LT(spurious_speed_after(0.00337, 300), 1e-10);
}

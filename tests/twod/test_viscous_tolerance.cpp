// The viscous solve's stopping rule resolves a small wave at small steps.
//
// The predictor's right-hand side b holds rho u^n / dt, so a residual measured against ||b||
// grows as the step shrinks while the change the step makes shrinks with it. A wave of
// amplitude 2.5e-6 m on the section 7 flow at cfl 0.1 then fell below the old tolerance
// (1e-8 ||b||): most steps kept the extrapolated initial guess, unsolved, and the wave grew 4 %
// faster than at cfl 0.4 (docs/twod-validation.md §2). The rule is now relative to the change,
// ||b - A u*|| <= tol ||b - A u^n|| (tol = 1e-4). Here a wave of 1e-8 m (2.5e-6 h0) runs 200
// steps of 1e-5 s with the default iterative solve and with a direct factorisation; the wave's
// vertical velocity must agree to 3e-4 of its size. Measured: 1.0e-4, the tolerance's own
// level, at 1.0 iterations per step; with the old rule 1.3e-3 at 0.47 iterations per step (more
// than half of the steps unsolved). The change b - A u^n also holds the base flow's own (the
// light fluid accelerating, the discrete profile settling), so for a wave far smaller still
// (1e-10 m) the rule is that much looser on the wave (1e-2; the old rule 0.32).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/steady_state.hpp"
#include "twod/initial_state.hpp"
#include "twod/solver.hpp"
#include "twod/viscous_step.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {

struct SmallWaveRun {
  std::vector<double> w;
  double viscous_iterations_per_step = 0.0;
};

SmallWaveRun small_wave(LinearSolverKind viscous_solver, double a0) {
  SolverParams params;
  params.zeta = degrees_to_radians(28.5);
  params.viscous_solver = viscous_solver;
  params.dt_initial = 1e-5;
  params.dt_max = 1e-5;
  params.threads = 1;
  const double h0 = 0.004, Lx = 0.02;
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, h0);
  const SteadyState steady = steady_state(curve, params.zeta, h0);
  const Grid g(16, 32, Lx, mid_cell_domain_height(h0, 32));
  Solver solver(g, params, make_initial_state(g, perturbed_bagnold(steady, a0, Lx), params));
  solver.advance_to(2e-3);
  const RunStatistics st = solver.statistics();
  return {solver.state().w, double(st.viscous_iterations) / double(std::max(st.steps, 1L))};
}

double norm(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

}  // namespace

TEST(ViscousTolerance, ASmallWaveAtSmallStepsMatchesTheDirectSolve) {
  const double a0 = 1e-8;
  const SmallWaveRun iterative = small_wave(LinearSolverKind::LineRelaxation, a0);
  const SmallWaveRun direct = small_wave(LinearSolverKind::Direct, a0);
  std::vector<double> diff(direct.w.size());
  for (std::size_t c = 0; c < diff.size(); ++c) diff[c] = iterative.w[c] - direct.w[c];
  const double relative = norm(diff) / norm(direct.w);
  std::printf("iterative against direct: |dw|/|w| = %.3e, %.2f iterations per step\n", relative,
              iterative.viscous_iterations_per_step);
  EXPECT_GT(norm(direct.w), 0.0);
  EXPECT_LT(relative, 3e-4);
}

// The rule's three regimes. A step whose change is large (the 12 cm eigenmode rollwave's splash
// and droplets: 1e-4 of the change was looser than 1e-8 ||b|| there, and the run diverged at
// 7.3 s) is held to the former 1e-8 ||b||; a small change to 1e-4 of itself; a step that changes
// nothing to the round-off floor. The solver's run of that case is a `paper` test
// (tests/analysis/cases/test_case_paper.cpp).
TEST(ViscousTolerance, TheStopIsRelativeToTheChangeButNeverLooserThanTheFormerRule) {
  const double b = 1e6;
  EXPECT_DOUBLE_EQ(viscous_stop_tolerance(1e-4, 1e-2, b), 1e-12);  // a change of 1e-8 ||b||
  EXPECT_DOUBLE_EQ(viscous_stop_tolerance(1e-4, 1e2, b), 1e-8);    // 1e-4 ||b||: 1e-4 of it
  EXPECT_DOUBLE_EQ(viscous_stop_tolerance(1e-4, 1.0, b), 1e-10);   // 1e-6 ||b||
  EXPECT_DOUBLE_EQ(viscous_stop_tolerance(1e-4, 1e4, b), 1e-8);    // 1e-2 ||b||: capped
  EXPECT_DOUBLE_EQ(viscous_stop_tolerance(1e-4, 0.0, b), 1e-12);   // nothing to solve
  EXPECT_DOUBLE_EQ(viscous_stop_tolerance(1e-4, 1.0, 0.0), 1e-4);  // b = 0
}

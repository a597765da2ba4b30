// The open top of the 2D domain holds p = 0 at z = Lz for the whole pressure, not only for the
// projection's increment (dp = 0 there). The top face's predicted velocity takes the pressure
// gradient to p = 0 at the lid and the other tendencies of the face below (twod/viscous_step.cpp),
// so the two top faces' pressure accelerations are equal up to the change of the top cell's
// divergence, and the wave's pressure (Fourier mode 1 along x) in the top cell is a third of the
// cell below's: linear to 0 at the lid, half a cell above the top centre. Before, the predictor
// copied the face below's velocity, pressure force included; the top cell's pressure then
// drifted with the flow, the wave's pressure stayed uniform up to the lid (ratio 0.99 here, at 35
// times the present value), and the heavier light fluid (0.15 kg/m^3, 1e-4 Pa s) cost the growth 19
// times what its theory says (docs/twod-validation.md §5).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "common/steady_state.hpp"
#include "twod/initial_state.hpp"
#include "twod/run.hpp"
#include "twod/solver.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {
// |Fourier mode 1 along x| of a cell-centred field in row k.
double mode1_in_row(const Grid& g, const std::vector<double>& q, int k) {
  std::complex<double> c = 0.0;
  for (int i = 0; i < g.nx; ++i)
    c += q[g.at(i, k)] * std::polar(1.0, -2.0 * std::numbers::pi * g.xc(i) / g.Lx);
  return 2.0 * std::abs(c) / g.nx;
}
}  // namespace

TEST(OpenTop, TheWholePressureIsZeroAtTheLid) {
  SolverParams params;
  params.zeta = degrees_to_radians(28.5);
  const double h0 = 0.004, Lx = 0.08, a0 = 0.05 * h0;
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, h0);
  const SteadyState steady = steady_state(curve, params.zeta, h0);
  const Grid g(40, 16, Lx, 2.0 * h0);
  Solver solver(g, params, make_initial_state(g, perturbed_bagnold(steady, a0, Lx), params));
  RunSchedule schedule;
  schedule.t_end = 0.1;
  schedule.dt_out = 0.05;
  const RunResult result = run(solver, SurfaceSeries::uniform_grid(Lx, g.nx, h0), schedule);
  ASSERT_TRUE(result.completed()) << result.message;

  // The wave's pressure (Fourier mode 1 along x) in the top cell and the cell below it.
  const Fields& s = solver.state();
  const double p_top = mode1_in_row(g, s.p, g.nz - 1), p_below = mode1_in_row(g, s.p, g.nz - 2);
  std::printf("wave's pressure: top cell %.3g Pa, the cell below %.3g Pa\n", p_top, p_below);
  ASSERT_GT(p_below, 0.0);
  // p = 0 at the lid with the two top faces' pressure accelerations equal (the top face's
  // balance, with the tendencies of the face below) makes p_top = p_below / 3.
  EXPECT_NEAR(p_top / p_below, 1.0 / 3.0, 0.05);
}

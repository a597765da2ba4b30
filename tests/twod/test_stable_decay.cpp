// (e) A perturbed layer on a slope where every theory predicts decay relaxes to the flat Bagnold
// state. At 24 deg with h0 = 4 mm and the regularised curve, F = 0.54 is below the critical 2/3
// of (7.11) with chi = 1 (and below 2/sqrt(5) for the Bagnold shape factor 5/4), so every
// wavelength decays; the exact 2D linear stability gives -3.159 1/s at Lx = 4 cm. The layer starts
// from (7.2) with a0 = 0.1 h0 on a coarse 32 x 16 grid (8 cells per h0, surface on a face). Over
// the second half of 1 s the mode-1 amplitude must decay exponentially (a straight ln|h_1| fit);
// at 1 s the surface must be flat to within that remaining mode (3 % of a0), and the flux back at
// the Bagnold flux (5.5) of the depth h0 within the O(dz^1.5) error of the steady-profile test at
// this grid. With the default step, which gives the surface row the hydrostatic pressure force
// on its grains (SolverParams::surface_row_pressure), the decay is at the exact 2D rate within
// 15 % (measured -3.35 1/s), which the first test asserts; with the standard MAC force on that
// row (the option off) it is -3.51 1/s (-3.61 with the backward-Euler stress, -4.24 with the
// former first-order step), and the second test asserts only the relaxation.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "analysis/linear2d/linear_stability_2d.hpp"
#include "analysis/spectral/spectral_growth.hpp"
#include "analysis/theory/dispersion.hpp"
#include "common/steady_state.hpp"
#include "twod/diagnostics.hpp"
#include "twod/initial_state.hpp"
#include "twod/run.hpp"
#include "twod/solver.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {
// The decay rate of mode 1 over the second half of 1 s; checks the relaxation on the way.
double relax(const SolverParams& params_in, double flat_within) {
  SolverParams params = params_in;
  params.zeta = degrees_to_radians(24.0);
  const double h0 = 0.004, Lx = 0.04, a0 = 0.1 * h0;
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, h0);
  const SteadyState steady = steady_state(curve, params.zeta, h0);
  EXPECT_LT(steady.Fr, critical_froude(1.0));
  const double rate_chi1 = dispersion_mode(steady, 1.0, Lx).growth_rate;
  const double rate_chi54 = dispersion_mode(steady, 1.25, Lx).growth_rate;
  EXPECT_LT(rate_chi1, 0.0);
  EXPECT_LT(rate_chi54, 0.0);

  const Grid g(32, 16, Lx, 2 * h0);
  Solver solver(g, params, make_initial_state(g, perturbed_bagnold(steady, a0, Lx), params));
  RunSchedule schedule;
  schedule.t_end = 1.0;
  schedule.dt_out = 0.025;
  const RunResult run_result = run(solver, SurfaceSeries::uniform_grid(Lx, g.nx, h0), schedule);
  EXPECT_TRUE(run_result.completed()) << run_result.message;
  const SurfaceSeries& series = run_result.series;
  if (series.nt() != 41u) {
    ADD_FAILURE() << "samples: " << series.nt();
    return 0.0;
  }
  const auto amp = mode_amplitudes(series, 1);
  const double a_start = 2.0 * std::abs(amp.front()) / g.nx,
               a_end = 2.0 * std::abs(amp.back()) / g.nx;
  EXPECT_NEAR(a_start, a0, 0.01 * a0);
  EXPECT_LT(a_end, 0.05 * a0);
  for (std::size_t n = 21; n < amp.size(); ++n) EXPECT_LT(std::abs(amp[n]), std::abs(amp[n - 1]));
  std::vector<double> ln(amp.size());
  for (std::size_t n = 0; n < amp.size(); ++n) ln[n] = std::log(std::abs(amp[n]));
  const LinearFit fit = fit_line(series.t, ln, 20, amp.size() - 1);
  std::printf("decay rate %.3f 1/s (R^2 %.5f); depth-averaged (7.11): chi=1 %.3f, chi=5/4 %.3f\n",
              fit.slope, fit.r2, rate_chi1, rate_chi54);
  EXPECT_LT(fit.slope, 0.0);
  EXPECT_GT(fit.r2, 0.99);
  const auto h = surface_heights(g, solver.state().f);
  for (double v : h) EXPECT_NEAR(v, h0, flat_within * a0);  // what is left is the decaying mode
  EXPECT_NEAR(mean_flux(g, solver.state()), steady.u_mean * h0, 0.02 * steady.u_mean * h0);
  EXPECT_LT(std::abs(solver.statistics().mass_error()), 1e-12);
  return fit.slope;
}

double exact_2d_rate() {
  const Material material;
  const MuCurve curve(CurveKind::Regularised, material, 0.004);
  const SteadyState steady = steady_state(curve, degrees_to_radians(24.0), 0.004);
  Linear2DOptions opt;
  opt.N_check = 0;
  return linear_stability_2d(steady, curve, 0.04, opt).surface.growth_rate;
}
}  // namespace

TEST(StableDecay, PerturbedLayerRelaxesToBagnoldAtTheExact2DRate) {
  const double rate_2d = exact_2d_rate();
  ASSERT_LT(rate_2d, 0.0);
  // flat within the mode the theory leaves at 1 s (0.042 a0), with room for harmonics
  const double rate = relax(SolverParams{}, 1.5 * std::exp(rate_2d * 1.0));
  std::printf("exact 2D linear rate %.3f 1/s\n", rate_2d);
  EXPECT_NEAR(rate, rate_2d, 0.15 * std::abs(rate_2d));
}

TEST(StableDecay, WithTheStandardSurfaceRowForceTheLayerRelaxesToBagnold) {
  SolverParams params;
  params.surface_row_pressure = false;
  // flat within the mode the exact 2D theory leaves at 1 s, as in the test above (with the BDF2
  // step this option decays at -3.51 1/s, closer to the theory's -3.16 than the -3.61 of
  // backward Euler, so more of the mode is left at 1 s: 3.1 % of a0 against 2.7 %)
  const double rate = relax(params, 1.5 * std::exp(exact_2d_rate() * 1.0));
  EXPECT_LT(rate, 0.0);
}

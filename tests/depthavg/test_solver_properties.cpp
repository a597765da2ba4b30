// Properties of the depth-averaged solver that hold exactly: mass is conserved to round-off
// (conservative fluxes, and Newton solves that keep column sums, see cvode_integrator.hpp);
// the uniform steady state (h0, u_bar_0) stays steady; the unlimited and limited reconstructions
// approach each other on a rollwave as the grid is refined, and so do the lab-frame and
// co-moving-frame solutions (in the linear regime at the scheme's second order: the co-moving
// output is the lab-frame solution, up to the discretisation error); the stop flag keeps what was
// computed; a diverging run stops and says when, where and in which quantity.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "analysis/spectral/wave_speed.hpp"
#include "analysis/theory/dispersion.hpp"
#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"
#include "depthavg/initial_state.hpp"
#include "depthavg/solver.hpp"

namespace granbench {
namespace {

struct Fixture {
  Material material;
  MuCurve curve{CurveKind::Regularised, material, 4e-3};
  SteadyState base = steady_state(curve, degrees_to_radians(28.5), 4e-3);
};

depthavg::RunResult rollwave(const Fixture& f, depthavg::Reconstruction rec, std::size_t nx,
                             double t_end, double frame_speed = 0.0) {
  depthavg::SpaceParams space;
  space.frame_speed = frame_speed;
  space.Lx = 0.08;
  space.nx = nx;
  space.reconstruction = rec;
  depthavg::IntegratorParams integ;
  const depthavg::Solver solver(f.base, f.curve, space, integ);
  depthavg::InitialParams init;  // (7.2), a0 = 0.2 mm, with a little noise in every mode
  init.noise = 1e-3;
  depthavg::OutputParams out;
  out.t_end = t_end;
  out.dt_out = 0.01;
  return solver.run(depthavg::initial_state(solver.rhs(), init), out);
}

TEST(DepthAvgSolver, MassIsConservedToRoundOff) {
  const Fixture f;
  for (auto rec : {depthavg::Reconstruction::Central, depthavg::Reconstruction::VanAlbada}) {
    const auto r = rollwave(f, rec, 64, 0.5);
    ASSERT_EQ(r.status, depthavg::RunStatus::Completed) << r.message;
    EXPECT_LT(r.mass_error(), 1e-13) << depthavg::reconstruction_name(rec);
  }
}

TEST(DepthAvgSolver, DirectAndKrylovNewtonSolversAgreeToTheTolerance) {
  // The same nonlinear rollwave (0.5 s from (7.2), a0 = 0.2 mm, lab frame) with each way of
  // solving the Newton systems (cvode_integrator.hpp): they are the same BDF steps solved to
  // CVODE's tolerance, so the heights agree to about rtol times the wave's height; the direct
  // solver needs no Krylov iterations and one F per Newton iteration.
  const Fixture f;
  depthavg::RunResult r[2];
  const depthavg::LinearSolver solvers[2] = {depthavg::LinearSolver::Direct,
                                             depthavg::LinearSolver::KrylovBand};
  for (int i = 0; i < 2; ++i) {
    depthavg::SpaceParams space;
    space.nx = 96;
    depthavg::IntegratorParams integ;
    integ.rtol = 1e-9;
    integ.atol = 1e-13;
    integ.linear_solver = solvers[i];
    const depthavg::Solver solver(f.base, f.curve, space, integ);
    depthavg::OutputParams out;
    out.t_end = 0.5;
    out.dt_out = 0.05;
    r[i] = solver.run(depthavg::initial_state(solver.rhs(), {}), out);
    ASSERT_EQ(r[i].status, depthavg::RunStatus::Completed) << r[i].message;
    EXPECT_LT(r[i].mass_error(), 1e-13);
  }
  EXPECT_EQ(r[0].stats.linear_iterations, 0);
  EXPECT_GT(r[1].stats.linear_iterations, 0);
  EXPECT_EQ(r[0].stats.rhs_evals_jtimes, 0);
  const auto ha = r[0].series.h_at(r[0].series.nt() - 1),
             hb = r[1].series.h_at(r[1].series.nt() - 1);
  double diff = 0.0, lo = ha[0], hi = ha[0];
  for (std::size_t j = 0; j < ha.size(); ++j) {
    diff = std::max(diff, std::fabs(ha[j] - hb[j]));
    lo = std::min(lo, ha[j]);
    hi = std::max(hi, ha[j]);
  }
  EXPECT_GT(hi - lo, 4e-4);  // nonlinear: the wave is well beyond a0
  EXPECT_LT(diff, 1e-6 * (hi - lo));
}

TEST(DepthAvgSolver, UniformSteadyStateStaysSteady) {
  const Fixture f;
  depthavg::SpaceParams space;
  space.nx = 64;
  const depthavg::Solver solver(f.base, f.curve, space, {});
  depthavg::InitialParams init;
  init.a0 = 0.0;
  const auto U0 = depthavg::initial_state(solver.rhs(), init);
  depthavg::OutputParams out;
  out.t_end = 2.0;
  out.dt_out = 0.5;
  const auto r = solver.run(U0, out);
  ASSERT_EQ(r.status, depthavg::RunStatus::Completed) << r.message;
  double dev = 0.0;
  for (std::size_t i = 0; i < U0.size(); ++i)
    dev = std::max(dev, std::fabs(r.final_state[i] - U0[i]) / std::fabs(U0[i]));
  EXPECT_LT(dev, 1e-12);
}

TEST(DepthAvgSolver, CentralAndLimitedReconstructionsConvergeTogetherOnARollwave) {
  // From (7.2) with a0 = 0.2 mm the wave saturates within 0.3 s, so by t = 0.5 s it is
  // nonlinear. The MC limiter clips extrema (first order there) and is the more dissipative;
  // the two must approach each other as the grid is refined.
  const Fixture f;
  double diff[2], amp = 0.0;
  const std::size_t nx[2] = {48, 96};
  for (int i = 0; i < 2; ++i) {
    const auto a = rollwave(f, depthavg::Reconstruction::Central, nx[i], 0.5);
    const auto b = rollwave(f, depthavg::Reconstruction::MC, nx[i], 0.5);
    ASSERT_EQ(a.status, depthavg::RunStatus::Completed);
    ASSERT_EQ(b.status, depthavg::RunStatus::Completed);
    EXPECT_LT(b.mass_error(), 1e-13);
    const auto ha = a.series.h_at(a.series.nt() - 1), hb = b.series.h_at(b.series.nt() - 1);
    diff[i] = 0.0;
    amp = 0.0;
    for (std::size_t j = 0; j < ha.size(); ++j) {
      diff[i] = std::max(diff[i], std::fabs(ha[j] - hb[j]));
      amp = std::max(amp, std::fabs(ha[j] - f.base.h0));
    }
  }
  EXPECT_GT(amp, 4e-4);               // the wave has grown well beyond a0 = 0.2 mm
  EXPECT_LT(diff[1], 0.9 * diff[0]);  // closer on the finer grid
  EXPECT_LT(diff[1], 0.35 * amp);
}

TEST(DepthAvgSolver, CoMovingFrameGivesTheLabFrameSolution) {
  // The same rollwave solved in the lab frame and in a frame moving at 0.84 m/s (near the wave's
  // speed), the co-moving samples translated back: the wave speeds agree, and the heights
  // approach each other as the grid is refined (they differ by the schemes' advection errors).
  const Fixture f;
  double dmax[2];
  const std::size_t nx[2] = {64, 128};
  for (int i = 0; i < 2; ++i) {
    const auto a = rollwave(f, depthavg::Reconstruction::Central, nx[i], 1.0);
    const auto b = rollwave(f, depthavg::Reconstruction::Central, nx[i], 1.0, 0.84);
    ASSERT_EQ(a.status, depthavg::RunStatus::Completed);
    ASSERT_EQ(b.status, depthavg::RunStatus::Completed);
    EXPECT_LT(b.mass_error(), 1e-13);
    EXPECT_LT(b.stats.steps, a.stats.steps / 3);  // the point of the co-moving frame
    const auto ha = a.series.h_at(a.series.nt() - 1), hb = b.series.h_at(b.series.nt() - 1);
    dmax[i] = std::fabs(*std::max_element(ha.begin(), ha.end()) -
                        *std::max_element(hb.begin(), hb.end()));
    if (i == 1) {
      const double ca = wave_speed(a.series, 0.5, 1.0).speed;
      const double cb = wave_speed(b.series, 0.5, 1.0).speed;
      EXPECT_NEAR(ca, cb, 1e-3 * ca);
      EXPECT_LT(dmax[i], 0.05 * (*std::max_element(ha.begin(), ha.end()) - f.base.h0));
    }
  }
  EXPECT_LT(dmax[1], dmax[0]);
}

TEST(DepthAvgSolver, CoMovingOutputConvergesToTheLabFrameOutputAtSecondOrder) {
  // `run`, `compare` and `sweep` solve in the frame of the (7.11) phase speed by default and
  // translate every sample back to the lab frame. Here the seeded eigenmode (7.10) at the linear
  // amplitude 0.02 mm, tolerances far below the grid's error: the lab-frame and co-moving series
  // differ at every sample only by the two frames' discretisation errors, which fall at second
  // order as the grid is refined. (They cannot agree to the solver tolerance on one grid: the grid
  // moves with the frame, so the two runs are two discretisations of the same equations.)
  const Fixture f;
  const DispersionMode exact = dispersion_mode(f.base, 1.0, 0.08);  // (7.11)
  double diff[3];
  const std::size_t nx[3] = {64, 128, 256};
  for (int i = 0; i < 3; ++i) {
    depthavg::RunResult r[2];
    for (int frame = 0; frame < 2; ++frame) {
      depthavg::SpaceParams space;
      space.Lx = 0.08;
      space.nx = nx[i];
      space.frame_speed = frame == 0 ? 0.0 : exact.phase_speed;
      depthavg::IntegratorParams integ;
      integ.rtol = 1e-10;
      integ.atol = 1e-12;
      const depthavg::Solver solver(f.base, f.curve, space, integ);
      depthavg::InitialParams init;
      init.kind = depthavg::InitKind::Eigenmode;
      init.a0 = 2e-5;
      depthavg::OutputParams out;
      out.t_end = 0.5;
      out.dt_out = 0.05;
      r[frame] = solver.run(depthavg::initial_state(solver.rhs(), init, exact.lambda_hat), out);
      ASSERT_EQ(r[frame].status, depthavg::RunStatus::Completed) << r[frame].message;
    }
    // largest difference over all samples, relative to the perturbation's amplitude there
    diff[i] = 0.0;
    for (std::size_t n = 1; n < r[0].series.nt(); ++n) {
      const auto a = r[0].series.h_at(n), b = r[1].series.h_at(n);
      double amp = 0.0, d = 0.0;
      for (std::size_t j = 0; j < a.size(); ++j) {
        amp = std::max(amp, std::fabs(a[j] - f.base.h0));
        d = std::max(d, std::fabs(a[j] - b[j]));
      }
      diff[i] = std::max(diff[i], d / amp);
    }
    std::printf("nx = %zu: lab vs co-moving, largest relative difference %.3e\n", nx[i], diff[i]);
  }
  EXPECT_LT(diff[2], 3e-3);                      // measured 1.96e-3
  EXPECT_GT(std::log2(diff[0] / diff[1]), 1.7);  // second order
  EXPECT_GT(std::log2(diff[1] / diff[2]), 1.7);
}

TEST(DepthAvgSolver, StopFlagKeepsWhatWasComputed) {
  const Fixture f;
  depthavg::SpaceParams space;
  space.nx = 32;
  const depthavg::Solver solver(f.base, f.curve, space, {});
  const auto U0 = depthavg::initial_state(solver.rhs(), {});
  std::atomic<bool> stop{false};
  depthavg::RunCallbacks cb;
  cb.stop = &stop;
  int calls = 0;
  cb.progress = [&](double, double) {
    if (++calls == 3) stop = true;
  };
  depthavg::OutputParams out;
  out.t_end = 10.0;
  out.dt_out = 0.01;
  const auto r = solver.run(U0, out, cb);
  EXPECT_EQ(r.status, depthavg::RunStatus::Interrupted);
  EXPECT_EQ(r.series.nt(), 4u);  // t = 0 and three samples
  EXPECT_NEAR(r.t_reached, 0.03, 1e-12);
}

TEST(DepthAvgSolver, StopFlagIsSeenBetweenSamples) {
  // One sample interval of the whole run: before, the flag was looked at only after a sample, so a
  // run that needed many steps per sample ignored Ctrl-C for as long as the interval took (five
  // minutes for a stalled one). Now CVODE returns every steps_per_call steps and the flag is seen.
  const Fixture f;
  depthavg::SpaceParams space;
  space.nx = 64;
  const depthavg::Solver solver(f.base, f.curve, space, {});
  const auto U0 = depthavg::initial_state(solver.rhs(), {});
  std::atomic<bool> stop{true};  // raised before the run: it ends after the first chunk
  depthavg::RunCallbacks cb;
  cb.stop = &stop;
  depthavg::OutputParams out;
  out.t_end = 10.0;
  out.dt_out = 10.0;
  const auto r = solver.run(U0, out, cb);
  EXPECT_EQ(r.status, depthavg::RunStatus::Interrupted) << r.message;
  EXPECT_EQ(r.stats.steps, depthavg::IntegratorParams{}.steps_per_call);
  EXPECT_GT(r.t_reached, 0.0);
  EXPECT_LT(r.t_reached, 10.0);
  EXPECT_EQ(r.series.nt(), 1u);  // t = 0 only: the state between samples is not a sample
  EXPECT_NE(r.message.find("the last sample at t = 0"), std::string::npos) << r.message;
}

TEST(DepthAvgSolver, StepsTakenInChunksAreTheStepsOfOneCall) {
  // CVODE resumes where a chunk returned: one sample interval of thousands of steps, taken in
  // chunks of 2 000 (the default) or of 500, or in one call, ends in the same state, bit for bit.
  const Fixture f;
  depthavg::SpaceParams space;
  space.nx = 128;
  depthavg::OutputParams out;
  out.t_end = 1.0;
  out.dt_out = 1.0;
  std::vector<depthavg::RunResult> runs;
  for (long steps_per_call : {2000L, 500L, 100000000L}) {
    depthavg::IntegratorParams integ;
    integ.steps_per_call = steps_per_call;
    const depthavg::Solver solver(f.base, f.curve, space, integ);
    runs.push_back(solver.run(depthavg::initial_state(solver.rhs(), {}), out));
    ASSERT_EQ(runs.back().status, depthavg::RunStatus::Completed) << runs.back().message;
  }
  ASSERT_GT(runs[0].stats.steps, 2 * 2000);  // several chunks
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_EQ(runs[i].stats.steps, runs[0].stats.steps);
    EXPECT_EQ(runs[i].final_state, runs[0].final_state);
  }
}

TEST(DepthAvgSolver, AStalledIntegrationIsReportedInsteadOfGroundThrough) {
  // At 40 degrees the unlimited reconstruction lets the rollwave's fronts oscillate until the
  // depth nearly vanishes in a trough, and CVODE's steps fall to a millionth of a cell's crossing
  // time. It used to grind through two million steps (five minutes at 256 cells) before giving
  // up; now a thousand steps per crossing time (at least 10 000) in one interval end the run,
  // diverged, with the step sizes in the message. The limited reconstruction runs the same case.
  const Material material;
  const MuCurve curve{CurveKind::Regularised, material, 4e-3};
  const SteadyState base = steady_state(curve, degrees_to_radians(40.0), 4e-3);
  depthavg::SpaceParams space;
  space.nx = 32;
  depthavg::OutputParams out;
  out.t_end = 0.1;
  out.dt_out = 0.005;
  const depthavg::Solver central(base, curve, space, {});
  const auto r = central.run(depthavg::initial_state(central.rhs(), {}), out);
  EXPECT_EQ(r.status, depthavg::RunStatus::Diverged);
  EXPECT_NE(r.message.find("the integration stalled"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("a wave takes to cross a cell"), std::string::npos) << r.message;
  EXPECT_LT(r.stats.steps, 100000) << r.message;  // CVODE's own limit: two million an interval
  space.reconstruction = depthavg::Reconstruction::VanAlbada;
  const depthavg::Solver limited(base, curve, space, {});
  const auto l = limited.run(depthavg::initial_state(limited.rhs(), {}), out);
  EXPECT_EQ(l.status, depthavg::RunStatus::Completed) << l.message;
}

TEST(DepthAvgSolver, DivergenceIsReportedWithTimePlaceAndQuantity) {
  const Fixture f;
  depthavg::SpaceParams space;
  space.nx = 32;
  const depthavg::Solver solver(f.base, f.curve, space, {});
  auto U0 = depthavg::initial_state(solver.rhs(), {});
  U0[2 * 7 + 1] = std::numeric_limits<double>::quiet_NaN();  // a broken momentum in cell 7
  depthavg::OutputParams out;
  out.t_end = 1.0;
  const auto r = solver.run(U0, out);
  EXPECT_EQ(r.status, depthavg::RunStatus::Diverged);
  EXPECT_NE(r.message.find("t = "), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("x = 0.01875 m"), std::string::npos) << r.message;  // cell 7
  EXPECT_NE(r.message.find("non-finite h*u"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace granbench

// Runs of either model on one ChuteCase; see model_runs.hpp.
//
// Seeding. With Seed::Eigenmode each model starts from the unstable normal mode of its own exact
// linear theory, so that it grows as one clean mode from t = 0:
//   depthavg  the mode (7.10) of (7.7)-(7.8) with the model's shape factor chi (dispersion.hpp);
//   twod      the least-stable surface mode of the 2D linear stability (linear_stability_2d.hpp):
//             surface h0 + a0 cos(kx) and u = U0(z) + Re(a0 u_hat(z) e^{ikx}); the 2D solver
//             derives w from continuity and p from hydrostatics (initial_state.hpp).
// With Seed::Sine both start from (7.2) with the Bagnold velocity of the local depth, as §7 does.
#include "analysis/comparison/model_runs.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <future>
#include <numbers>
#include <stdexcept>

#include "analysis/comparison/eigenmode_seed.hpp"
#include "analysis/comparison/run_command.hpp"
#include "analysis/linear2d/eigenmode.hpp"
#include "analysis/linear2d/linear_stability_2d.hpp"
#include "analysis/spectral/surface_measurement.hpp"
#include "analysis/theory/dispersion.hpp"
#include "depthavg/initial_state.hpp"
#include "depthavg/solver.hpp"
#include "twod/diagnostics.hpp"
#include "twod/initial_state.hpp"
#include "twod/run.hpp"
#include "twod/solver.hpp"

namespace granbench {

double sampling_interval(const ChuteCase& c, double wave_speed_estimate) {
  if (c.dt_out > 0.0) return c.dt_out;
  const double period = c.Lx / std::max(std::fabs(wave_speed_estimate), 1e-6);
  const double dt = std::min(0.02, period / 20.0);
  // a whole number of samples up to t_end, so that the last one is on the uniform grid the
  // measurement needs (surface_measurement.hpp)
  return c.t_end / std::ceil(c.t_end / dt - 1e-9);
}

namespace {

// The sampling intervals of the runs: the wave's phase is resolved with the speed of (7.11) with
// the run's chi, and for the 2D model with chi = 5/4, close to the 2D linear speed
// (docs/design.md §10).
double depthavg_sampling_interval(const ChuteCase& c, const SteadyState& base, double chi) {
  return sampling_interval(c, dispersion_mode(base, chi, c.Lx).phase_speed);
}
double twod_sampling_interval(const ChuteCase& c, const SteadyState& base) {
  return sampling_interval(c, dispersion_mode(base, 1.25, c.Lx).phase_speed);
}

}  // namespace

std::string depthavg_command_of(const ChuteCase& c, const DepthAvgSettings& s) {
  return depthavg_run_command(c, s, depthavg_sampling_interval(c, c.steady(), s.chi));
}

std::string twod_command_of(const ChuteCase& c, const TwodSettings& s) {
  return twod_run_command(c, s, twod_sampling_interval(c, c.steady()));
}

DepthAvgSettings DepthAvgSettings::limited_where_it_saturates(const ChuteCase& c,
                                                              double growth_rate) const {
  DepthAvgSettings r = *this;
  const double bound = MeasureOptions{}.linear_bound * c.h0;  // where the measurement stops
  if (reconstruction == depthavg::Reconstruction::Central &&
      c.a0 * std::exp(growth_rate * c.t_end) > bound)
    r.reconstruction = depthavg::Reconstruction::VanAlbada;
  return r;
}

ModelRun run_depthavg(const ChuteCase& c, const DepthAvgSettings& s, const RunControl& ctl) {
  const MuCurve curve = c.make_curve();
  const SteadyState base = steady_state(curve, degrees_to_radians(c.angle_deg), c.h0);
  const DispersionMode exact = dispersion_mode(base, s.chi, c.Lx);

  depthavg::SpaceParams space;
  space.Lx = c.Lx;
  space.nx = s.nx;
  space.chi = s.chi;
  space.reconstruction = s.reconstruction;
  space.frame_speed = s.co_moving ? exact.phase_speed : 0.0;
  depthavg::IntegratorParams integ;
  integ.rtol = s.rtol;
  integ.atol = 1e-4 * s.rtol * c.h0;
  depthavg::InitialParams init;
  init.kind = c.seed == Seed::Eigenmode ? depthavg::InitKind::Eigenmode : depthavg::InitKind::Sine;
  init.a0 = c.a0;
  depthavg::OutputParams out;
  out.t_end = c.t_end;
  out.dt_out = depthavg_sampling_interval(c, base, s.chi);

  const depthavg::Solver solver(base, curve, space, integ);
  const auto U0 = depthavg::initial_state(solver.rhs(), init, exact.lambda_hat);
  depthavg::RunCallbacks callbacks;
  if (ctl.progress)
    callbacks.progress = [&](double t, double te) { ctl.progress("depthavg", t, te); };
  callbacks.stop = ctl.stop;
  depthavg::RunResult r = solver.run(U0, out, callbacks);

  ModelRun m;
  m.model = "depthavg";
  m.series = std::move(r.series);
  m.outcome = r.status;
  m.message = r.message;
  m.steps = r.stats.steps;
  m.wall_seconds = r.wall_seconds;
  m.mass_error = r.mass_error();
  m.flux = r.flux_final;
  m.seeded_growth_rate = exact.growth_rate;
  m.dt_out = out.dt_out;
  m.run_command = depthavg_run_command(c, s, out.dt_out);
  m.nx = static_cast<int>(s.nx);
  return m;
}

namespace {

// The 2D initial condition of the seeded eigenmode (see the file comment).
twod::InitialCondition eigenmode_condition(const SteadyState& base, const MuCurve& curve,
                                           const ChuteCase& c, int N, double& growth) {
  Linear2DOptions opt;
  opt.N = N;
  opt.N_check = 0;
  const linear2d::Eigenmode mode = linear2d::surface_eigenmode(base, curve, c.Lx, opt);
  growth = mode.growth_rate();
  return eigenmode_initial_condition(mode, c.a0);
}

}  // namespace

GridPreset grid_preset(const std::string& name) {
  // (the aimed deficits: 3/4 of the 25 % the coarse grid is held to, and of the 10 % of the
  // others)
  if (name == "coarse") return {80, 32, 128, 0.1875};
  if (name == "default") return {160, 64, 256, 0.075};
  if (name == "fine") return {320, 128, 512, 0.075};
  throw std::invalid_argument("grid_preset: unknown resolution '" + name + "'");
}

namespace {

// run_twod; with partner_done, the run uses s.threads - 1 threads (at least 1) until the flag
// is raised (checked at each sample), then s.threads.
ModelRun run_twod_alongside(const ChuteCase& c, const TwodSettings& s, const RunControl& ctl,
                            const std::atomic<bool>* partner_done) {
  const MuCurve curve = c.make_curve();
  const SteadyState base = steady_state(curve, degrees_to_radians(c.angle_deg), c.h0);
  twod::Grid grid(s.nx, s.nz, c.Lx, s.domain_height(c.h0));
  grid.frame_speed = s.frame_fraction * base.u_surface;  // (twod/frame.hpp)
  twod::SolverParams params = twod_solver_params(c, s);
  params.threads = partner_done ? std::max(1, s.threads - 1) : s.threads;

  ModelRun m;
  m.model = "twod";
  twod::InitialCondition ic =
      c.seed == Seed::Eigenmode
          ? eigenmode_condition(base, curve, c, s.chebyshev_N, m.seeded_growth_rate)
          : twod::perturbed_bagnold(base, c.a0, c.Lx);
  twod::Solver solver(grid, params, twod::make_initial_state(grid, ic, params));

  twod::RunSchedule schedule;
  schedule.t_end = c.t_end;
  schedule.dt_out = twod_sampling_interval(c, base);
  twod::RunHooks hooks;
  hooks.stop = ctl.stop;
  hooks.sample = [&](const twod::Solver& sv, const SurfaceSeries&) {
    if (partner_done && *partner_done && solver.params().threads != s.threads)
      solver.set_threads(s.threads);  // the partner's core is free
    if (ctl.progress) ctl.progress("twod", sv.state().t, c.t_end);
  };
  twod::RunResult r =
      twod::run(solver, SurfaceSeries::uniform_grid(c.Lx, static_cast<std::size_t>(s.nx), c.h0),
                schedule, hooks);
  // A failure (a linear solve, memory) keeps the samples up to it, like an interruption.
  m.outcome = r.status;
  m.message = r.message;
  m.series = std::move(r.series);
  m.wall_seconds = r.wall_seconds;
  const auto stats = solver.statistics();
  m.steps = stats.steps;
  m.mass_error = std::fabs(stats.mass_error());
  m.flux = twod::mean_flux(grid, solver.state());
  const auto rs = twod::rheology_stats(grid, solver.state().f, solver.properties().I_c, curve);
  m.I_min = rs.I_min;
  m.I_max = rs.I_max;
  m.illposed_fraction = rs.illposed_fraction;
  m.dt_out = schedule.dt_out;
  m.run_command = twod_run_command(c, s, schedule.dt_out);
  m.nx = s.nx;
  m.nz = s.nz;
  return m;
}

}  // namespace

ModelRun run_twod(const ChuteCase& c, const TwodSettings& s, const RunControl& ctl) {
  return run_twod_alongside(c, s, ctl, nullptr);
}

std::pair<ModelRun, ModelRun> run_both(const ChuteCase& c, const DepthAvgSettings& depthavg,
                                       const TwodSettings& twod, const RunControl& ctl,
                                       const std::function<void()>& after_depthavg) {
  std::atomic<bool> depthavg_done{false};
  auto d = std::async(std::launch::async, [&] {
    struct Done {  // raised however run_depthavg ends, exceptions included
      std::atomic<bool>& flag;
      ~Done() { flag = true; }
    } done{depthavg_done};
    ModelRun r = run_depthavg(c, depthavg, ctl);
    if (after_depthavg) after_depthavg();
    return r;
  });
  auto t = std::async(std::launch::async,
                      [&] { return run_twod_alongside(c, twod, ctl, &depthavg_done); });
  // both futures are waited for before anything is rethrown: neither thread outlives the flag
  std::exception_ptr error;
  ModelRun depthavg_run, twod_run;
  try {
    depthavg_run = d.get();
  } catch (...) {
    error = std::current_exception();
  }
  try {
    twod_run = t.get();
  } catch (...) {
    if (!error) error = std::current_exception();
  }
  if (error) std::rethrow_exception(error);
  return {std::move(depthavg_run), std::move(twod_run)};
}

}  // namespace granbench

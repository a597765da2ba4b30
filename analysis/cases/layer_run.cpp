// The uniform-layer run of §5.2 and §6.2 (layer_run.hpp): initial Bagnold state of one curve and
// slope, then the 2D run (twod/run.hpp) with evenly spaced samples, each recorded here.
#include "analysis/cases/layer_run.hpp"

#include <cmath>
#include <limits>
#include <random>

#include "common/steady_state.hpp"
#include "twod/diagnostics.hpp"
#include "twod/initial_state.hpp"
#include "twod/properties.hpp"
#include "twod/run.hpp"
#include "twod/solver.hpp"
#include "twod/viscosity_pressure.hpp"

namespace granbench::cases {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Downslope averages and the I field of the current state. I is evaluated from the current
// velocity and the grains' effective pressure (the solver's own I is one step old).
void take_sample(const twod::Solver& solver, LayerRunRecord& r) {
  const twod::Grid& g = solver.grid();
  const twod::Fields& s = solver.state();
  twod::Properties props = solver.properties();
  std::vector<double> p_eff;
  twod::effective_pressure(g, solver.params(), s.p, p_eff);
  twod::update_viscosity(g, s, p_eff, solver.viscosity_model(), props);
  std::vector<double> u_mean(g.nz, 0.0), I_mean(g.nz, nan), field(g.cells(), nan);
  for (int k = 0; k < g.nz; ++k) {
    double sum_I = 0.0;
    int granular = 0;
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t c = g.at(i, k);
      u_mean[k] += s.u[c] / g.nx;
      // A cell counts as granular when at least half full (the rule of rheology_stats).
      if (s.f[c] >= 0.5 && std::isfinite(props.I_c[c])) {
        field[c] = props.I_c[c];
        sum_I += props.I_c[c];
        ++granular;
      }
    }
    if (granular > 0) I_mean[k] = sum_I / granular;
  }
  r.t.push_back(s.t);
  r.u_profile.push_back(std::move(u_mean));
  r.I_profile.push_back(std::move(I_mean));
  r.I_field.push_back(std::move(field));
  r.max_speed.push_back(twod::max_speed(s));
  r.illposed_fraction.push_back(
      twod::rheology_stats(g, s.f, props.I_c, solver.viscosity_model().curve()).illposed_fraction);
}

}  // namespace

LayerRunRecord run_layer(const LayerRunSpec& spec, const LayerRunProgress& progress) {
  const Material& material = spec.params.rheology.material;
  const MuCurve initial_curve(spec.initial_curve, material, spec.h0);
  const SteadyState initial =
      steady_state(initial_curve, spec.initial_zeta, spec.h0);  // (5.4)-(5.5)
  const twod::Grid grid(spec.nx, spec.nz, spec.Lx, spec.Lz);
  twod::Fields start =
      twod::make_initial_state(grid, twod::perturbed_bagnold(initial, 0.0, spec.Lx), spec.params);
  // u (1 + noise r), r uniform in [-1, 1]; the first projection restores continuity.
  std::mt19937_64 random(spec.seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  if (spec.noise > 0.0)
    for (double& u : start.u) u *= 1.0 + spec.noise * uniform(random);
  twod::Solver solver(grid, spec.params, std::move(start));
  LayerRunRecord r;
  r.label = spec.label;
  r.nx = spec.nx, r.nz = spec.nz, r.Lx = spec.Lx, r.Lz = spec.Lz;
  r.initial_I = initial.I_zeta;
  for (int k = 0; k < grid.nz; ++k) r.z.push_back(grid.zc(k));

  // Samples at n t_end / (samples - 1) (twod/run.hpp); the SurfaceSeries it keeps is not used.
  twod::RunSchedule schedule;
  schedule.t_end = spec.t_end;
  schedule.dt_out = spec.t_end / std::max(1, spec.samples - 1);
  twod::RunHooks hooks;
  hooks.stop = progress.stop;
  hooks.sample = [&](const twod::Solver& s, const SurfaceSeries&) {
    take_sample(s, r);
    if (progress.report) progress.report(r, s.state().t);
  };
  const twod::RunResult result = twod::run(
      solver, SurfaceSeries::uniform_grid(spec.Lx, static_cast<std::size_t>(spec.nx), spec.h0),
      schedule, hooks);
  r.status = run_status_name(result.status);
  r.message = result.message;
  const twod::RunStatistics st = solver.statistics();
  r.t_reached = solver.state().t;
  r.steps = st.steps;
  r.mass_error = st.mass_error();
  r.wall_seconds = result.wall_seconds;
  return r;
}

}  // namespace granbench::cases

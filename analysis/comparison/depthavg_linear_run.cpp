// Seeded normal-mode run and its spectral measurement; see
// analysis/comparison/depthavg_linear_run.hpp.
#include "analysis/comparison/depthavg_linear_run.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "depthavg/initial_state.hpp"

namespace granbench::depthavg {

LinearRunResult linear_run(const SteadyState& base, const MuCurve& curve, double chi, double Lx,
                           const LinearRunParams& p) {
  LinearRunResult r;
  r.Lx = Lx;
  const double wavelength = Lx / p.mode;
  r.exact = dispersion_mode(base, chi, wavelength);  // (7.11), (7.13)

  SpaceParams space;
  space.Lx = Lx;
  space.nx = p.nx;
  space.chi = chi;
  space.reconstruction = p.reconstruction;
  space.frame_speed = p.co_moving ? r.exact.phase_speed : 0.0;
  IntegratorParams integ;
  integ.rtol = p.tolerance * p.amplitude;
  integ.atol = integ.rtol * base.h0;
  InitialParams init;
  init.kind = InitKind::Eigenmode;
  init.a0 = p.amplitude * base.h0;
  init.mode = p.mode;

  const double period = wavelength / std::max(std::fabs(r.exact.phase_speed), 1e-6);
  OutputParams out;
  out.t_end = p.t_end > 0.0
                  ? p.t_end
                  : std::min(5.0, std::max(4.0 * period, 0.5 / std::fabs(r.exact.growth_rate)));
  out.dt_out = std::min(period / 16.0, out.t_end / 40.0);
  r.t_end = out.t_end;

  const Solver solver(base, curve, space, integ);
  const auto U0 = initial_state(solver.rhs(), init, r.exact.lambda_hat);
  const RunResult run = solver.run(U0, out);
  r.stats = run.stats;
  r.wall_seconds = run.wall_seconds;
  r.mass_error = run.mass_error();
  r.ok = run.status == RunStatus::Completed;
  r.message = run.message;
  MeasureOptions m;
  m.mode = p.mode;
  m.seeded_phase_speed = r.exact.phase_speed;
  r.measured = measure_surface_series(run.series, m);
  return r;
}

}  // namespace granbench::depthavg

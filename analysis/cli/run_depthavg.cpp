// granbench run --model depthavg: the depth-averaged mu(I) equations (7.3)-(7.5) with shape
// factor chi, from (7.2) or the normal mode (7.10), integrated by CVODE; the seeded mode's growth
// rate and phase speed (and the other waves at its wavenumber) measured by the matrix pencil fit
// of surface_measurement.hpp beside the exact relation (7.11) (chi-generalised),
// the paper's estimator (7.12), and the speed of the developed wave (its dominant Fourier mode's
// phase speed, wave_speed.hpp).
// The options and paths are checked before any work; a stop (SIGINT, SIGTERM) or a failure keeps
// what was computed (failure_policy.hpp).
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

#include "analysis/cli/commands.hpp"
#include "analysis/cli/depthavg_report.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/cli/run_model.hpp"
#include "analysis/comparison/model_runs.hpp"
#include "analysis/spectral/measurement.hpp"
#include "analysis/theory/dispersion.hpp"
#include "common/steady_state.hpp"
#include "depthavg/initial_state.hpp"
#include "depthavg/solver.hpp"

namespace granbench::cli {

void run_depthavg(const RunOptions& o, const DepthAvgOptions& mo) {
  const double chi = parse_chi(mo.chi);
  const MuCurve curve = o.flow.make_curve();
  const SteadyState base = o.flow.steady();
  const double wavelength = o.Lx / o.mode;
  const DispersionMode exact = dispersion_mode(base, chi, wavelength);  // (7.11) with chi

  depthavg::SpaceParams space;
  space.Lx = o.Lx;
  space.nx = o.nx;
  space.chi = chi;
  ChuteCase seeded = o.flow.chute(o.Lx);  // the seed and run length that --limiter auto judges
  seeded.a0 = o.a0;
  seeded.t_end = o.t_end;
  const bool seed_saturates =
      DepthAvgSettings{}.limited_where_it_saturates(seeded, exact.growth_rate).reconstruction !=
      depthavg::Reconstruction::Central;
  space.reconstruction = limiter_for_seed(mo.limiter, seed_saturates);
  space.frame_speed = parse_frame_speed(mo.frame_speed, exact.phase_speed);
  depthavg::IntegratorParams integ;
  integ.rtol = o.rtol;
  integ.atol = o.atol;
  // In the co-moving frame the wave is nearly steady and BDF orders 3-5 hold the step at their
  // stability band (params.hpp): order 2 takes ~2x fewer steps there. In the lab frame the steps
  // are accuracy-limited and order 5 takes ~4x fewer than order 2 (docs/performance.md).
  integ.max_order = o.bdf_order > 0 ? o.bdf_order : space.frame_speed != 0.0 ? 2 : 5;
  depthavg::InitialParams init;
  init.kind = o.init == "eigenmode" ? depthavg::InitKind::Eigenmode : depthavg::InitKind::Sine;
  init.a0 = o.a0;
  init.mode = o.mode;
  init.noise = o.noise;
  init.seed = o.seed;
  depthavg::OutputParams out;
  out.t_end = o.t_end;
  // Automatic sampling: the fastest characteristic moves at most a wavelength/8 per sample.
  const double g_cos = base.material.g * std::cos(base.zeta), u0 = base.u_mean;
  const double c_max = chi * u0 + std::sqrt(chi * (chi - 1.0) * u0 * u0 + g_cos * base.h0);
  // Automatic: no more than kMaxSamples, however long the run (an explicit --dt-out is refused).
  out.dt_out = o.dt_out > 0.0 ? o.dt_out
                              : std::max(std::min(0.01, wavelength / (8.0 * c_max)),
                                         o.t_end / double(kMaxSamples));

  require_record_count("--dt-out", o.t_end, out.dt_out, kMaxSamples, "samples");
  if (!o.output.out.empty()) require_writable(o.output.out, "--out");
  const auto claim = claim_output(o.output.out, "--out");  // held until the file is written

  const depthavg::Solver solver(base, curve, space, integ);
  const auto U0 = depthavg::initial_state(solver.rhs(), init, exact.lambda_hat);

  const InterruptGuard guard(InterruptGuard::Signals::IntAndTerm);
  depthavg::RunCallbacks cb;
  cb.stop = guard.flag();
  const bool progress = progress_enabled(o.output);
  if (progress)
    cb.progress = [wall0 = std::chrono::steady_clock::now()](double t, double t_end) {
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      std::cerr << "\r  t = " << std::fixed << std::setprecision(3) << t << " / " << t_end << " s, "
                << eta_text(wall, 0.0, t, t_end) << "    " << std::flush;
    };
  const depthavg::RunResult r = solver.run(U0, out, cb);
  if (progress) std::cerr << "\n";

  // The seeded mode is the component nearest the (7.11) phase speed; a saturated wave (e.g. (7.2)
  // at Lx = 8 cm, which saturates within 0.3 s) has no clean linear window and gives a reason.
  MeasureOptions measure_opt;
  measure_opt.mode = o.mode;
  measure_opt.seeded_phase_speed = exact.phase_speed;
  const Measurement m = measure(r.series, measure_opt);
  const auto last_h = r.series.h_at(r.series.nt() - 1);
  double h_mean = 0.0;
  for (double v : last_h) h_mean += v / static_cast<double>(last_h.size());
  const char* status = run_status_name(r.status);

  nlohmann::json j = {{"model", "depthavg"},
                      {"status", status},
                      {"message", r.message},
                      {"t_reached", r.t_reached},
                      {"cells", nlohmann::json::array({o.nx})},  // as in compare and sweep
                      {"steps", r.stats.steps},
                      {"rhs_evals", r.stats.total_rhs_evals()},
                      {"jacobian_evals", r.stats.jacobian_evals},
                      {"linear_solves", r.stats.linear_solves},
                      {"wall_seconds", r.wall_seconds},
                      {"mass_error", r.mass_error()},
                      {"h_mean", h_mean},
                      {"flux", r.flux_final},
                      {"chi", chi},
                      {"growth_rate_exact", exact.growth_rate},
                      {"phase_speed_exact", exact.phase_speed},
                      {"dt_out", out.dt_out},
                      {"frame_speed", space.frame_speed},
                      {"limiter", depthavg::reconstruction_name(space.reconstruction)},
                      {"limiter_option", mo.limiter},
                      {"F", base.Fr},
                      {"R", base.R},
                      {"Gamma", base.Gamma},
                      {"u_mean", base.u_mean}};
  j.update(to_json(m));  // the measurement, spelled as in every command

  if (!o.output.out.empty()) write_depthavg_run(o, mo, space, base, r, j);

  print_depthavg_run(o, j, m);
  if (r.status == depthavg::RunStatus::Interrupted)
    throw CommandFailed(r.message + "; the samples computed so far were kept", guard.exit_code());
  if (r.status == depthavg::RunStatus::Failed)
    throw CommandFailed(r.message + "; the samples computed so far were kept", kExitRunFailed);
  if (r.status == depthavg::RunStatus::Diverged) {
    // The unlimited slopes suit linear runs; a front steep enough to oscillate is their usual end.
    const bool unlimited = space.reconstruction == depthavg::Reconstruction::Central;
    throw CommandFailed(
        r.message + (unlimited ? "; the slopes were unlimited (--limiter central): "
                                 "--limiter vanalbada keeps steep fronts free of oscillations"
                               : ""),
        kExitRunFailed);
  }
}

}  // namespace granbench::cli

// What `granbench compare` reports (compare_report.hpp): each model's JSON and the table, with
// n/a and the reason wherever there is no measurement (never a 0 that reads as a result).
#include "analysis/cli/compare_report.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>

#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/extrapolation_report.hpp"
#include "analysis/spectral/measurement.hpp"

namespace granbench::cli {

nlohmann::json model_json(const ModelRun& r, const Measurement& m) {
  nlohmann::json j = to_json(m);  // the measurement, spelled as in every command
  j.update({{"steps", r.steps},
            {"wall_seconds", r.wall_seconds},
            {"mass_error", r.mass_error},
            {"flux", r.flux},
            {"completed", r.outcome == RunOutcome::Completed},
            {"run_command", r.run_command}});
  if (!r.message.empty()) j["message"] = r.message;
  j["cells"] = r.model == "twod" ? nlohmann::json{r.nx, r.nz} : nlohmann::json{r.nx};
  if (r.model == "twod") {
    j["I_range"] = {r.I_min, r.I_max};
    j["illposed_fraction"] = r.illposed_fraction;
  }
  return j;
}

namespace {

// One measured row: growth and phase speed with their deviation from the reference theory, or
// "n/a" and the reason when there was no clean window; then any other wave carrying more than 10 %
// of the seeded wave's amplitude at the window start, on its own line.
void print_measured(const char* label, const SurfaceMeasurement& m, const TheoryValue& ref,
                    const char* ref_name) {
  auto rel = [](double a, double b) { return 100.0 * (a - b) / std::fabs(b); };
  std::cout << std::setprecision(4) << "  " << std::left << std::setw(25) << label << std::right;
  if (!m.found()) {
    std::cout << std::setw(12) << "n/a" << std::setw(20) << "n/a"
              << "   (not measured: " << m.reason << ")\n";
    return;
  }
  std::cout << std::setw(12) << m.growth_rate << std::setw(20) << m.phase_speed << "   vs "
            << ref_name << ": " << std::setprecision(2) << std::showpos
            << rel(m.growth_rate, ref.growth_rate) << " %, " << rel(m.phase_speed, ref.phase_speed)
            << " %\n"
            << std::noshowpos;
  const double seeded = m.modes[m.seeded].amplitude;
  for (std::size_t i = 0; i < m.modes.size(); ++i) {
    if (i == m.seeded || !(m.modes[i].amplitude > 0.1 * seeded)) continue;
    std::cout << std::setprecision(4) << "    + another wave         " << std::setw(12)
              << m.modes[i].growth_rate << std::setw(20) << m.modes[i].phase_speed
              << "   amplitude " << std::setprecision(0) << 100.0 * m.modes[i].amplitude / seeded
              << " % of the seeded wave's at t = " << std::setprecision(3) << m.t_first << " s\n";
  }
}

// The extrapolated 2D row (compare --extrapolate), or n/a and the reason.
void print_extrapolated(const TwodExtrapolation& e, const TheoryValue& ref) {
  std::cout << std::setprecision(4) << "  " << std::left << std::setw(25) << "twod (extrapolated)"
            << std::right;
  if (!e.found()) {
    std::cout << std::setw(12) << "n/a" << std::setw(20) << ""
              << "   (not extrapolated: " << e.reason << ")\n";
    return;
  }
  std::cout << std::setw(12) << e.growth.value << std::setw(20) << ""
            << "   vs 2D linear: " << std::setprecision(2) << std::showpos
            << 100.0 * (e.growth.value - ref.growth_rate) / std::fabs(ref.growth_rate) << " %"
            << std::noshowpos << std::setprecision(4) << " (bounds " << e.growth.low << " to "
            << e.growth.high << "; " << e.growth_rate_half_cells << " on " << e.nx << " x " << e.nz
            << ")\n";
}

}  // namespace

void print_table(const Comparison& c) {
  const auto& t = c.theory;
  std::cout << std::setprecision(4) << std::fixed << "granbench compare: Lx = " << c.chute.Lx
            << " m, angle " << c.chute.angle_deg << " deg, h0 = " << c.chute.h0 << " m, "
            << curve_name(c.chute.curve) << " curve, k_hat = " << t.k_hat << "\n\n"
            << "                           growth [1/s]   phase speed [m/s]\n"
            << "  exact (7.11), chi = 1    " << std::setw(12) << t.exact.growth_rate
            << std::setw(20) << t.exact.phase_speed << "\n"
            << "  exact, chi = 5/4         " << std::setw(12) << t.exact_bagnold.growth_rate
            << std::setw(20) << t.exact_bagnold.phase_speed << "\n"
            << "  exact 2D linear          " << std::setw(12) << t.exact_2d.growth_rate
            << std::setw(20) << t.exact_2d.phase_speed << "\n";
  print_measured("depthavg (measured)", c.depthavg_measured.spectral, t.exact, "(7.11)");
  print_measured("twod (measured)", c.twod_measured.spectral, t.exact_2d, "2D linear");
  if (c.twod_extrapolation) print_extrapolated(*c.twod_extrapolation, t.exact_2d);
  for (const auto* m : {&c.depthavg_measured, &c.twod_measured}) {
    const char* name = m == &c.depthavg_measured ? "depthavg" : "twod";
    const SurfaceMeasurement& w = m->spectral;
    std::cout << std::setprecision(3) << "  " << name;
    if (w.found())
      std::cout << " fitted over t = [" << w.t_first << ", " << w.t_last << "] s, "
                << w.modes.size() << " wave(s), relative residual " << std::scientific
                << std::setprecision(1) << w.relative_residual << std::fixed
                << std::setprecision(3);
    else
      std::cout << " growth not measured";
    if (whole_run_fitted(*m))
      std::cout << "; whole-run fit of ln|h_k| " << m->whole_run.slope
                << " 1/s (R^2 = " << m->whole_run.r2 << ")\n";
    else
      std::cout << "; whole-run fit of ln|h_k| n/a (fewer than 3 samples)\n";
    if (!w.note.empty()) std::cout << "  " << name << ": " << w.note << "\n";
    if (m->saturated && m->wave)
      std::cout << "  " << name << " saturated wave: speed " << std::setprecision(4)
                << m->wave->speed << " m/s (Fourier mode " << m->wave->mode
                << ", last fifth), amplitude " << m->final_amplitude * 1e3 << " mm\n";
  }
  std::cout << std::setprecision(1) << "\n  runs: depthavg " << c.depthavg.wall_seconds
            << " s wall (" << c.depthavg.nx << " cells), twod " << c.twod.wall_seconds
            << " s wall (" << c.twod.nx << " x " << c.twod.nz << " cells, " << c.twod.steps
            << " steps), 2D mass error " << std::scientific << std::setprecision(1)
            << c.twod.mass_error << std::fixed << ", I in [" << std::setprecision(3) << c.twod.I_min
            << ", " << c.twod.I_max << "], ill-posed fraction " << c.twod.illposed_fraction << "\n";
  if (c.twod_extrapolation)
    std::cout << std::setprecision(1)
              << "  twod on half the cells across the layer: " << c.twod_extrapolation->wall_seconds
              << " s wall (" << c.twod_extrapolation->steps
              << " steps); extrapolated with order 1.4 in the cell height, bounds from 1.3 and "
                 "1.7 (docs/twod-validation.md §3)\n";
}

nlohmann::json compare_json(const Comparison& c, int viscosity_passes,
                            const std::vector<std::string>& warnings, const std::string& h5,
                            const std::string& png) {
  nlohmann::json twod = model_json(c.twod, c.twod_measured);
  twod["extrapolated"] = c.twod_extrapolation ? extrapolation_json(*c.twod_extrapolation,
                                                                   c.theory.exact_2d.growth_rate)
                                              : nlohmann::json(nullptr);
  return nlohmann::json(
      {{"Lx", c.chute.Lx},
       {"k_hat", c.theory.k_hat},
       {"exact",
        {{"growth_rate", c.theory.exact.growth_rate}, {"phase_speed", c.theory.exact.phase_speed}}},
       {"exact_bagnold",
        {{"growth_rate", c.theory.exact_bagnold.growth_rate},
         {"phase_speed", c.theory.exact_bagnold.phase_speed}}},
       {"exact_2d",
        {{"growth_rate", c.theory.exact_2d.growth_rate},
         {"phase_speed", c.theory.exact_2d.phase_speed},
         {"convergence", c.theory.exact_2d_convergence}}},
       {"depthavg", model_json(c.depthavg, c.depthavg_measured)},
       {"twod", twod},
       {"twod_viscosity_passes", viscosity_passes},
       {"warnings", warnings},
       {"out", h5},
       {"plot", png}});
}

void throw_unless_both_completed(const ModelRun& depthavg, const ModelRun& twod,
                                 const InterruptGuard& guard, const std::string& h5) {
  for (const ModelRun* r : {&depthavg, &twod}) {
    if (r->outcome == RunOutcome::Interrupted)
      throw CommandFailed("interrupted; what was computed is in " + h5, guard.exit_code());
    if (r->outcome == RunOutcome::Diverged || r->outcome == RunOutcome::Failed)
      throw CommandFailed(r->model + " run " + r->message +  // ("diverged at t = ...")
                              "; data up to then in " + h5,
                          kExitRunFailed);
  }
}

}  // namespace granbench::cli

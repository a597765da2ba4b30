// What `granbench run --model twod` shows: the progress line, the JSON keys of a run, the table,
// and the exit code of the failure policy (run_twod.hpp).
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>

#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/run_twod.hpp"
#include "analysis/spectral/measurement.hpp"
#include "twod/diagnostics.hpp"

namespace granbench::cli {

std::function<void(const twod::Solver&, const SurfaceSeries&)> twod_progress_line(
    const RunOptions& o, bool show) {
  if (!show) return {};
  const auto wall0 = std::chrono::steady_clock::now();
  // t_start: the first sample's time (a restart's is the checkpoint's), for the ETA
  return [wall0, t_end = o.t_end, last = 0.0, t_start = -1.0](const twod::Solver& s,
                                                              const SurfaceSeries&) mutable {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    if (t_start < 0.0) t_start = s.state().t;
    if (wall - last <= 1.0) return;
    last = wall;
    std::cerr << "\r  t = " << std::fixed << std::setprecision(4) << s.state().t << " / " << t_end
              << " s, step " << s.statistics().steps << ", dt " << std::scientific
              << std::setprecision(2) << s.statistics().dt_last << " s, wall " << std::fixed
              << std::setprecision(0) << wall << " s, "
              << eta_text(wall, t_start, s.state().t, t_end) << "    " << std::flush;
  };
}

nlohmann::json twod_result_json(const twod::RunResult& res, const twod::Solver& solver,
                                const SteadyState& base, const Measurement& measured,
                                SeededTheory seeded, double dt_out) {
  const SurfaceSeries& kept = res.series;
  const twod::RunStatistics st = solver.statistics();
  const auto last_h = kept.h_at(kept.nt() - 1);
  double h_mean = 0.0;
  for (double v : last_h) h_mean += v / double(last_h.size());
  const double wall = res.wall_seconds;
  nlohmann::json j = {
      {"model", "twod"},
      {"t_reached", solver.state().t},
      {"steps", st.steps},
      {"viscous_iterations", st.viscous_iterations},
      {"projection_iterations", st.projection_iterations},
      {"wall_seconds", wall},
      {"cell_updates_per_second", double(st.steps) * solver.grid().cells() / std::max(wall, 1e-9)},
      {"mass_error", st.mass_error()},
      {"vof_clipped_volume", st.clipped_volume / std::max(st.initial_volume, 1e-300)},
      {"vof_substepped_steps", st.vof_substepped_steps},
      {"max_divergence", st.max_divergence},
      {"dt_min", st.dt_min},
      {"dt_max", st.dt_max},
      // the grid the run took (the default rule's or the options'), spelled as in compare and sweep
      {"cells", {solver.grid().nx, solver.grid().nz}},
      {"Lz", solver.grid().Lz},
      {"frame_speed", solver.grid().frame_speed},  // the grid's; the outputs are in the lab frame
      {"h_mean", h_mean},
      {"flux", twod::mean_flux(solver.grid(), solver.state())},
      {"growth_rate_theory", number_or_null(seeded.growth_rate)},
      {"phase_speed_theory", number_or_null(seeded.phase_speed)},
      {"I_range", std::isfinite(res.I_min) ? nlohmann::json{res.I_min, res.I_max} : nullptr},
      {"illposed_fraction", res.last.illposed_fraction},
      {"illposed_fraction_max", res.illposed_fraction_max},
      {"dt_out", dt_out},
      {"F", base.Fr},
      {"u_mean", base.u_mean}};
  j.update(to_json(measured));  // the measurement, spelled as in every command
  return j;
}

namespace {

// --extrapolate's line: the extrapolated growth, its bounds, the half grid's growth and cost, and
// its deviation from the exact 2D theory (when there is one); or the reason there is none.
void print_extrapolation(const TwodExtrapolation& e, const nlohmann::json& theory_growth) {
  std::cout << "  extrapolated     ";
  if (!e.found()) {
    std::cout << "- 1/s  (not extrapolated: " << e.reason << ")\n";
    return;
  }
  std::cout << e.growth.value << " 1/s (bounds " << e.growth.low << " to " << e.growth.high << "; "
            << e.growth_rate_half_cells << " on " << e.nx << " x " << e.nz << " in " << std::fixed
            << std::setprecision(1) << e.wall_seconds << " s wall)";
  if (!theory_growth.is_null())
    std::cout << std::setprecision(2) << std::showpos << ": "
              << 100.0 * (e.growth.value / theory_growth.get<double>() - 1.0) << " %"
              << std::noshowpos;
  std::cout << std::defaultfloat << std::setprecision(6) << "\n";
}

}  // namespace

void run_twod(const RunOptions& o, const TwodOptions& mo) {
  const InterruptGuard guard(InterruptGuard::Signals::IntAndTerm);
  const TwodRunReport r = run_twod_model(o, mo, guard.flag());
  const nlohmann::json& j = r.json;
  if (o.output.json) {
    print_json(j);
  } else {
    auto show = [&j](const char* key) {
      return j[key].is_null() ? std::string("-") : j[key].dump();
    };
    const SurfaceMeasurement& growth = r.measured.spectral;
    std::cout << "twod run (" << j["status"].get<std::string>() << "), " << o.flow.curve
              << " curve, angle " << o.flow.angle_deg << " deg, h0 = " << o.flow.h0 << " m, "
              << o.nx << " x " << mo.settings.nz << " cells on " << o.Lx << " x " << r.Lz << " m\n"
              << "  grid speed       " << j["frame_speed"].get<double>()
              << " m/s downslope (--twod-frame; every output is in the lab frame)\n"
              << "  t reached        " << j["t_reached"].get<double>() << " s in "
              << j["wall_seconds"].get<double>() << " s wall, " << j["steps"].get<long>()
              << " steps\n"
              << "  mass error       " << j["mass_error"].get<double>() << " (relative)\n"
              << "  h mean, flux     " << j["h_mean"].get<double>() << " m, "
              << j["flux"].get<double>() << " m^2/s\n"
              << "  growth rate      " << show("growth_rate") << " 1/s, phase speed "
              << show("phase_speed") << " m/s"
              << (growth.found() ? "" : "  (not measured: " + growth.reason + ")") << "\n";
    if (!j.at("growth_rate_theory").is_null()) {
      const double sigma = j.at("growth_rate_theory").get<double>(),
                   c = j.at("phase_speed_theory").get<double>();
      std::cout << "  exact 2D linear  " << sigma << " 1/s, " << c
                << " m/s (the seeded surface wave, stress-free surface)";
      if (growth.found())
        std::cout << std::fixed << std::setprecision(2) << std::showpos << ": measured "
                  << 100.0 * (j.at("growth_rate").get<double>() / sigma - 1.0) << " %, "
                  << 100.0 * (j.at("phase_speed").get<double>() / c - 1.0) << " %" << std::noshowpos
                  << std::defaultfloat << std::setprecision(6);
      std::cout << "\n";
    }
    if (r.extrapolation) print_extrapolation(*r.extrapolation, j.at("growth_rate_theory"));
    for (std::size_t i = 0; i < growth.modes.size(); ++i)
      if (i != growth.seeded)
        std::cout << "  other wave       growth " << growth.modes[i].growth_rate << " 1/s, speed "
                  << growth.modes[i].phase_speed << " m/s, amplitude "
                  << growth.modes[i].amplitude * 1e3 << " mm (seeded "
                  << growth.modes[growth.seeded].amplitude * 1e3 << " mm)\n";
    const auto& I = j["I_range"];
    std::cout << "  wave speed       " << show("wave_speed") << " m/s "
              << wave_speed_note(r.measured.wave) << "\n"
              << "  I range          "
              << (I.is_null() ? std::string("-")
                              : std::to_string(I[0].get<double>()) + " .. " +
                                    std::to_string(I[1].get<double>()))
              << ", ill-posed fraction " << j["illposed_fraction"].get<double>() << " (max "
              << j["illposed_fraction_max"].get<double>() << ")\n";
  }
  throw_unless_completed(r, guard);
  if (r.extrapolation && r.extrapolation->outcome == RunOutcome::Interrupted)
    throw CommandFailed("interrupted on half the cells across the layer; the run's output was kept",
                        guard.exit_code());
}

void throw_unless_completed(const TwodRunReport& r, const InterruptGuard& guard) {
  switch (r.status) {
    case twod::RunStatus::Completed:
      return;
    case twod::RunStatus::Interrupted:
      throw CommandFailed(r.message + "; the samples computed so far were kept", guard.exit_code());
    case twod::RunStatus::Diverged:
      throw CommandFailed(r.message, kExitRunFailed);
    case twod::RunStatus::Failed:
      throw CommandFailed(r.message + "; the samples computed so far were kept", kExitRunFailed);
  }
}

}  // namespace granbench::cli

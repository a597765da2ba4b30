// granbench compare: the main job. One chute flow (§7 defaults: 28.5 deg, h0 = 4 mm, Lz ~ 2 h0 with
// h0 mid-cell, regularised curve) run with both models on the same rheology, each measured with the
// same analysis code, beside the exact linear theories at the same k_hat: (7.11), its chi = 5/4
// form and the 2D linear stability. Prints the side-by-side table (or --json), writes compare.h5
// (both SurfaceSeries, the analysis, the resolved configuration) and compare.png (figure 12 style).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/compare_options.hpp"
#include "analysis/cli/compare_report.hpp"
#include "analysis/cli/compare_saturated.hpp"
#include "analysis/cli/extrapolation_report.hpp"
#include "analysis/cli/help_footer.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/cli/physics_warnings.hpp"
#include "analysis/cli/run_model.hpp"
#include "analysis/comparison/compare.hpp"
#include "analysis/comparison/compare_output.hpp"
#include "analysis/spectral/measurement.hpp"

namespace granbench::cli {

namespace {

// Why the depth-averaged run of compare limits its slopes (DepthAvgSettings::
// limited_where_it_saturates): where the seeded wave leaves the linear regime and what it costs.
std::string saturating_depthavg_note(const ChuteCase& c, double growth_rate) {
  const double bound = MeasureOptions{}.linear_bound;
  char when[160];
  if (c.a0 >= bound * c.h0)
    std::snprintf(when, sizeof when,
                  "starts at %.3g h0, at or above the linear bound (%.0f %% of h0)", c.a0 / c.h0,
                  100.0 * bound);
  else
    std::snprintf(when, sizeof when, "passes %.0f %% of h0 at t = %.3g s, before --t-end %.3g s",
                  100.0 * bound, std::log(bound * c.h0 / c.a0) / growth_rate, c.t_end);
  char buf[480];
  std::snprintf(buf, sizeof buf,
                "the seeded wave, growing at the (7.11) rate %.4g 1/s, %s, and steepens into "
                "fronts: the depth-averaged model limits its slopes there (--limiter vanalbada, "
                "about 0.1 %% off its linear growth; docs/comparison.md)",
                growth_rate, when);
  return std::string(buf);
}

void run_compare(const CompareOptions& o, const SaturatedOptions& saturated) {
  ChuteCase chute = o.flow.chute(o.Lx);
  chute.a0 = o.paper ? 2e-4 : o.a0;
  chute.seed = (o.paper || o.init == "sine") ? Seed::Sine : Seed::Eigenmode;
  chute.t_end = o.t_end;
  chute.dt_out = o.dt_out;
  (void)o.flow.steady();  // a slope with no steady flow is an error on --angle
  if (chute.a0 >= chute.h0) throw UsageError("--a0: must be below h0; valid range (0, h0)");
  const GridPreset res = grid_preset(o.resolution);
  // The exact theories first (about a second): the 2D growth sets the cells across the layer
  // near the cutoff, the 2D eigenmode seeds the 2D run. A case without them is refused below,
  // with the reason, before any run.
  std::optional<Theories> theory;
  try {
    theory = exact_theories(chute);
  } catch (const std::runtime_error&) {
  }
  TwodSettings twod;
  twod.nx = res.twod_nx;
  twod.nx = o.nx > 0 ? o.nx : twod.cells_along(chute.Lx);  // the preset's, as sweep's points
  twod.nz = res.twod_nz;
  twod.aimed_growth_deficit = res.twod_aimed_growth_deficit;
  if (o.nz > 0)
    twod.nz = o.nz;
  else  // as sweep's
    twod = twod.refined_across(chute.Lx, chute.steady(),
                               theory ? theory->exact_2d.growth_rate : NAN, chute.a0, chute.t_end);
  twod.viscosity_passes = o.viscosity_passes;
  twod.frame_fraction = o.twod_frame;
  twod.cfl = o.cfl;
  // About 1 kB of fields and solver work per 2D cell: 4 M cells is some 4 GB, the most a run of
  // this tool on a workstation should ask for; beyond it the allocation would fail mid-run.
  constexpr long kMaxTwodCells = 1L << 22;
  if (long(twod.nx) * twod.nz > kMaxTwodCells)
    throw UsageError("--nx: " + std::to_string(twod.nx) + " x " + std::to_string(twod.nz) +
                     " 2D cells; valid range nx * nz <= " + std::to_string(kMaxTwodCells));
  const double dz = twod.domain_height(chute.h0) / twod.nz;
  std::vector<std::string> warnings = twod_warnings(chute.steady(), dz, chute.Lx);
  if (auto w = twod_grid_cost_warning(twod.nx, twod.nz, chute.Lx / twod.nx / dz))
    warnings.push_back(*w);
  if (auto w = surface_on_face_warning(chute.h0, twod.domain_height(chute.h0), twod.nz))
    warnings.push_back(*w);
  if (o.extrapolate)
    if (auto w = thin_layer_extrapolation_warning(twod, chute.h0)) warnings.push_back(*w);
  if (!saturated.enabled)  // (the saturated wave does not rest on the early growth)
    if (auto w = large_step_sine_start_warning(twod.cfl, chute.seed == Seed::Sine))
      warnings.push_back(*w);
  DepthAvgSettings depthavg;
  depthavg.nx = o.nx_depthavg > 0 ? o.nx_depthavg : res.depthavg_nx;
  depthavg.co_moving = o.frame_speed == "linear";
  if (o.paper)  // the paper's amplitude saturates into a rollwave
    depthavg.reconstruction = depthavg::Reconstruction::MC;
  else if (theory) {
    depthavg = depthavg.limited_where_it_saturates(chute, theory->exact.growth_rate);
    if (depthavg.reconstruction != depthavg::Reconstruction::Central)
      warnings.push_back(saturating_depthavg_note(chute, theory->exact.growth_rate));
  }
  if (o.extrapolate && saturated.enabled)
    throw UsageError("--extrapolate: not with --saturated, whose wave leaves the linear regime");
  if (const double n = half_grid_cells_per_depth(twod, chute.h0);
      o.extrapolate && n < kGrowthDeficitFewestCellsPerDepth) {
    throw UsageError(too_few_cells_to_extrapolate(n) + ": --resolution default or fine, or --nz " +
                     std::to_string(nz_for_extrapolation(twod.domain_height(chute.h0), chute.h0)) +
                     " or more");
  }
  if (saturated.enabled)
    return run_compare_saturated(chute, depthavg, twod, o.output, saturated, warnings);

  const std::string h5 = o.output.out.empty() ? "compare.h5" : o.output.out;
  const std::string png = o.output.plot.empty() ? "compare.png" : o.output.plot;
  // Before any work (failure_policy.hpp): a path that cannot be written, or a sampling interval
  // that would fill memory, is a usage error, not a lost computation.
  require_writable(h5, "--out");
  const auto claim = claim_output(h5, "--out");  // held until compare.h5 is written
  require_writable(png, "--plot");
  if (o.dt_out > 0.0) require_record_count("--dt-out", o.t_end, o.dt_out, kMaxSamples, "samples");
  const InterruptGuard guard(InterruptGuard::Signals::IntAndTerm);
  std::mutex io;
  const bool show = progress_enabled(o.output);
  RunControl ctl;
  ctl.stop = guard.flag();
  if (show)
    ctl.progress = [&, wall0 = std::chrono::steady_clock::now()](const std::string& model, double t,
                                                                 double t_end) {
      std::lock_guard lock(io);
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      std::cerr << "\r  " << model << ": t = " << std::fixed << std::setprecision(2) << t << " / "
                << t_end << " s, " << eta_text(wall, 0.0, t, t_end) << "    " << std::flush;
    };

  Comparison c;
  c.chute = chute;
  c.base = chute.steady();
  // A case where the 2D linear stability has no surface mode (e.g. --Lx 1e9 --h0 29.1) is bad
  // input, refused before any run.
  try {
    c.theory = theory ? *theory : exact_theories(chute);
  } catch (const std::runtime_error& e) {
    throw UsageError("--Lx: no 2D linear surface mode at k_hat = 2 pi h0/Lx = " +
                     std::to_string(2.0 * std::numbers::pi * chute.h0 / chute.Lx) + " (" +
                     e.what() + "); choose another --Lx or --h0");
  }
  if (auto w = twod_growth_accuracy_warning(c.base, dz, chute.Lx, c.theory.exact_2d.growth_rate,
                                            twod.domain_height(chute.h0))) {
    // (not under the thin light layer, where the law's order did not hold)
    const bool can_extrapolate =
        half_grid_cells_per_depth(twod, chute.h0) >= kGrowthDeficitFewestCellsPerDepth &&
        !under_thin_light_layer(twod.domain_height(chute.h0), chute.h0);
    if (!o.extrapolate && can_extrapolate) *w += extrapolate_suggestion("the 2D model");
    warnings.push_back(*w);
  }
  print_warnings(warnings);  // once every check has passed
  // Both models at once (run_both shares the cores). With --extrapolate and two threads or more,
  // the 2D half grid follows the depth-averaged run on its core, on one thread (the small grid
  // shares threads poorly: at 8 cm 8.7 s on two against 6.5 s on one), while the first 2D run
  // waits for that core; on one thread it runs after both models.
  std::optional<TwodExtrapolation> half_grid;
  std::function<void()> half_grid_beside;
  if (o.extrapolate && twod.threads >= 2)
    half_grid_beside = [&] {
      TwodSettings one = twod;
      one.threads = 1;
      RunControl half_ctl = ctl;
      if (ctl.progress)
        half_ctl.progress = [&](const std::string&, double t, double t_end) {
          ctl.progress("twod on half the cells", t, t_end);
        };
      try {
        half_grid = run_half_grid(chute, one, c.theory.exact_2d.phase_speed, half_ctl);
      } catch (const std::exception& e) {
        half_grid.emplace();
        half_grid->outcome = RunOutcome::Failed;
        half_grid->reason =
            std::string("the run on half the cells across the layer failed: ") + e.what();
      }
    };
  std::tie(c.depthavg, c.twod) = run_both(chute, depthavg, twod, ctl, half_grid_beside);
  if (show) std::cerr << "\n";
  // Each model's seeded wave is the one nearest its own theory's phase speed.
  MeasureOptions depthavg_opt, twod_opt;
  depthavg_opt.seeded_phase_speed = c.theory.exact.phase_speed;  // chi = 1, as run
  twod_opt.seeded_phase_speed = c.theory.exact_2d.phase_speed;
  c.depthavg_measured = measure(c.depthavg.series, depthavg_opt);
  c.twod_measured = measure(c.twod.series, twod_opt);
  if (o.extrapolate && c.twod.outcome == RunOutcome::Completed &&
      c.depthavg.outcome == RunOutcome::Completed) {
    if (half_grid) {
      extrapolate_from(*half_grid, c.twod_measured.spectral.growth_rate);
      c.twod_extrapolation = *half_grid;
    } else {
      c.twod_extrapolation = extrapolate_twod_growth(
          chute, twod, c.twod_measured.spectral.growth_rate, c.theory.exact_2d.phase_speed, ctl);
      if (show) std::cerr << "\n";
    }
  }

  write_comparison(h5, c, twod, depthavg);
  plot_run("compare.py", h5, png, "",
           c.depthavg.outcome == RunOutcome::Completed && c.twod.outcome == RunOutcome::Completed);

  if (o.output.json) {
    nlohmann::json j = compare_json(c, twod.viscosity_passes, warnings, h5, png);
    j["depthavg"]["limiter"] = depthavg::reconstruction_name(depthavg.reconstruction);
    print_json(j);
  } else {
    print_table(c);
    std::cout << "  wrote " << h5 << " and " << png << "\n";
  }
  throw_unless_both_completed(c.depthavg, c.twod, guard, h5);
  if (c.twod_extrapolation && c.twod_extrapolation->outcome == RunOutcome::Interrupted)
    throw CommandFailed(
        "interrupted on half the cells across the layer; both models' runs are in " + h5,
        guard.exit_code());
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* sub = app.add_subcommand(
      "compare", "run both models on one chute flow and compare them with exact linear theory");
  add_flow_options(*sub, o->flow);
  add_output_options(*sub, o->output);
  add_threads_option(*sub);
  sub->footer(help_footer(
      {"granbench compare --Lx 0.08", "granbench compare --Lx 0.04 --resolution coarse --json",
       "granbench compare --Lx 0.12 --paper --t-end 10 --out rollwave.h5",
       "granbench compare --Lx 0.08 --saturated --threads 1"},
      {0, 2, 3, 130, 143}));
  add_compare_options(*sub, *o);
  auto saturated = std::make_shared<SaturatedOptions>();  // --saturated (compare_saturated.hpp)
  add_saturated_options(*sub, *saturated);
  sub->callback([o, saturated] { run_compare(*o, *saturated); });
}

}  // namespace granbench::cli

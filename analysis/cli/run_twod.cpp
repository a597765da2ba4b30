// granbench run --model twod: the §7 rollwave (or any periodic chute flow) with the full 2D
// incompressible mu(I) equations (2.9)-(2.11) and a VOF free surface (twod/).
//
//   granbench run --model twod --angle 28.5 --h0 0.004 --a0 2e-4 --Lx 0.08 --nx 256 --nz 64
//                 --t-end 10 --out roll.h5          (roll.h5 + roll.xdmf for ParaView)
//   granbench run --model twod --restart roll.checkpoint.h5 --t-end 10 --out roll.h5 ...
//
// Output: the SurfaceSeries h(x, t) (/surface), 2D snapshots (/snapshots, indexed by the XDMF
// file), the run statistics and every parameter (/parameters). The time loop is twod::run
// (twod/run.hpp), the files and checkpoints twod::RunOutput (twod/run_output.hpp); this file
// checks the options and paths, measures and reports.
#include "analysis/cli/run_twod.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "analysis/cli/extrapolation_report.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/cli/physics_warnings.hpp"
#include "analysis/comparison/eigenmode_seed.hpp"
#include "analysis/linear2d/eigenmode.hpp"
#include "common/companion_path.hpp"
#include "twod/checkpoint.hpp"
#include "twod/initial_state.hpp"
#include "twod/output.hpp"
#include "twod/run_output.hpp"

namespace granbench::cli {

namespace {

// The checkpoint to continue from, refused (UsageError naming the option) when it is not one or
// belongs to other physics, another grid or a later time.
std::optional<twod::Checkpoint> read_restart(const std::string& path, const twod::Grid& grid,
                                             const twod::SolverParams& params, double t_end) {
  if (path.empty()) return std::nullopt;
  twod::Checkpoint c;
  try {
    c = twod::read_checkpoint(path);
  } catch (const std::exception& e) {
    throw UsageError(std::string("--restart: ") + e.what());
  }
  const std::string mismatch = twod::restart_mismatch(c, grid, params);
  if (!mismatch.empty()) throw UsageError("--" + mismatch + " (checkpoint " + path + ")");
  if (!(c.state.t < t_end))
    throw UsageError("--t-end: must exceed the checkpoint's time " + std::to_string(c.state.t));
  return c;
}

// --extrapolate's conditions, checked before the run: one wavelength in the domain, as the half
// grid's case seeds it, and a half grid in the deficit law's range.
void check_extrapolation(const RunOptions& o, const TwodOptions& mo) {
  if (o.mode != 1)
    throw UsageError(
        "--extrapolate: needs --mode 1 (the run on half the cells seeds one "
        "wavelength over Lx); valid value 1");
  const TwodSettings fine = twod_run_settings(o, mo);
  if (const double n = half_grid_cells_per_depth(fine, o.flow.h0);
      n < kGrowthDeficitFewestCellsPerDepth)
    throw UsageError(
        too_few_cells_to_extrapolate(n) + ": --nz " +
        std::to_string(nz_for_extrapolation(fine.domain_height(o.flow.h0), o.flow.h0)) +
        " or more");
}

// After a completed run whose seeded wave was measured (extrapolate_twod_growth says so when it
// was not, without a second run), the same case on half the cells across the layer (sampled as the
// run was, the surface again mid-cell unless --Lz was given), with its own progress line; otherwise
// no second run and the reason.
TwodExtrapolation extrapolate(const RunOptions& o, const TwodOptions& mo, double dt_out,
                              const Measurement& measured, const twod::RunResult& first,
                              const SeededTheory& seeded, const std::atomic<bool>* stop) {
  TwodExtrapolation e;
  if (!first.completed()) {
    e.reason = "the run did not complete";
    return e;
  }
  if (std::isnan(seeded.phase_speed)) {
    e.reason = "no surface mode of the exact 2D theory to follow";
    return e;
  }
  ChuteCase c = chute_case(o);
  c.dt_out = dt_out;
  RunControl ctl;
  ctl.stop = stop;
  const bool show = progress_enabled(o.output);
  if (show)
    ctl.progress = [](const std::string&, double t, double t_end) {
      std::cerr << "\r  twod on half the cells across the layer: t = " << std::fixed
                << std::setprecision(3) << t << " / " << t_end << " s" << std::defaultfloat
                << std::flush;
    };
  try {
    e = extrapolate_twod_growth(c, twod_run_settings(o, mo), measured.spectral.growth_rate,
                                seeded.phase_speed, ctl);
  } catch (const std::exception& error) {
    e = TwodExtrapolation{};
    e.outcome = RunOutcome::Failed;
    e.reason = std::string("the run on half the cells across the layer failed: ") + error.what();
  }
  if (show) std::cerr << "\n";
  return e;
}

}  // namespace

TwodRunReport run_twod_model(const RunOptions& o, const TwodOptions& mo,
                             const std::atomic<bool>* stop) {
  using namespace granbench::twod;
  // --- options, paths and the restart, all before any work ---
  double Lz = 0.0;
  const SolverParams params = twod_run_params(o, mo, Lz);
  const SteadyState base = o.flow.steady();
  Grid grid(int(o.nx), mo.settings.nz, o.Lx, Lz);
  grid.frame_speed = mo.settings.frame_fraction * base.u_surface;  // (twod/frame.hpp)
  const double wavelength = o.Lx / o.mode;
  std::vector<std::string> warnings = twod_warnings(base, grid.dz, wavelength);
  if (auto w = twod_grid_cost_warning(grid.nx, grid.nz, grid.dx / grid.dz)) warnings.push_back(*w);
  if (auto w = surface_on_face_warning(base.h0, Lz, grid.nz)) warnings.push_back(*w);
  const std::optional<Checkpoint> restart = read_restart(mo.restart, grid, params, o.t_end);
  if (mo.extrapolate) check_extrapolation(o, mo);
  // Samples and snapshots on the grids k dt_out and j dt_snapshot from t = 0 (twod/run.hpp), so
  // a restart with the same options continues the first run's grids.
  RunSchedule schedule;
  schedule.t_end = o.t_end;
  // Automatic: no more than kMaxSamples, however long the run (an explicit --dt-out is refused).
  schedule.dt_out = o.dt_out > 0.0
                        ? o.dt_out
                        : std::max(std::min(0.01, wavelength / (8.0 * 2.0 * base.u_surface)),
                                   o.t_end / double(kMaxSamples));
  schedule.dt_snapshot = mo.dt_snapshot > 0.0 ? mo.dt_snapshot : o.t_end / 10.0;
  schedule.dt_checkpoint = mo.checkpoint_every;
  require_record_count("--dt-out", o.t_end, schedule.dt_out, kMaxSamples, "samples");
  require_record_count("--dt-snapshot", o.t_end, schedule.dt_snapshot, kMaxSnapshots, "snapshots");
  RunFiles files;
  files.out = o.output.out;
  files.checkpoint = !mo.checkpoint.empty()  ? mo.checkpoint
                     : !o.output.out.empty() ? companion_path(o.output.out, ".checkpoint.h5")
                                             : std::string("twod.checkpoint.h5");
  if (!files.out.empty()) {
    try {  // a name ParaView's XDMF readers cannot open is bad input, refused before the run
      twod::check_xdmf_file_name(std::filesystem::path(files.out).filename().string());
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    require_writable(files.out, "--out");
    require_writable(companion_path(files.out, ".xdmf"), "--out");
  }
  require_writable(files.checkpoint, "--checkpoint");
  const auto claim = claim_output(files.out, "--out");  // held for the run
  if (restart) files.earlier_snapshots = restart->snapshot_times;

  // --- initial state: (7.2), or the least-stable surface mode of the exact 2D linear theory ---
  // The surface mode's phase speed also identifies the seeded wave in the measurement.
  std::optional<linear2d::Eigenmode> eigenmode;
  try {
    eigenmode = linear2d::surface_eigenmode(base, o.flow.make_curve(), wavelength);
  } catch (const std::exception&) {
    if (o.init == "eigenmode") throw;
  }
  const SeededTheory seeded =
      eigenmode ? SeededTheory{eigenmode->growth_rate(), eigenmode->phase_speed()} : SeededTheory{};
  if (eigenmode)
    if (auto w = twod_growth_accuracy_warning(base, grid.dz, wavelength, eigenmode->growth_rate(),
                                              grid.Lz)) {
      if (!mo.extrapolate && o.mode == 1 && !under_thin_light_layer(grid.Lz, o.flow.h0) &&
          half_grid_cells_per_depth(twod_run_settings(o, mo), o.flow.h0) >=
              kGrowthDeficitFewestCellsPerDepth)
        *w += extrapolate_suggestion("the wave");
      warnings.push_back(*w);
    }
  if (mo.extrapolate)
    if (auto w = thin_layer_extrapolation_warning(twod_run_settings(o, mo), o.flow.h0))
      warnings.push_back(*w);
  if (auto w = large_step_sine_start_warning(params.cfl, o.init == "sine")) warnings.push_back(*w);
  Solver solver(grid, params,
                restart ? restart->state
                        : make_initial_state(grid,
                                             o.init == "eigenmode"
                                                 ? eigenmode_initial_condition(*eigenmode, o.a0)
                                                 : perturbed_bagnold(base, o.a0, wavelength),
                                             params));
  if (restart) resume_from(solver, *restart);
  SurfaceSeries series = restart && restart->series.nt() > 0
                             ? restart->series
                             : SurfaceSeries::uniform_grid(o.Lx, o.nx, o.flow.h0);
  std::optional<RunOutput> output;
  try {
    output.emplace(files, grid, params, [&o](H5Writer& h5) {
      h5.attribute("/", "a0", o.a0);
      h5.attribute("/", "h0", o.flow.h0);
      h5.attribute("/", "t_end", o.t_end);
    });
  } catch (const std::runtime_error& e) {
    throw UsageError("--out: " + std::string(e.what()));
  }

  print_warnings(warnings);  // once every check has passed
  // --- the run ---
  RunHooks hooks;
  hooks.stop = stop;
  hooks.sample = twod_progress_line(o, progress_enabled(o.output));
  output->attach(hooks);
  const RunResult res = twod::run(solver, std::move(series), schedule, hooks);
  if (progress_enabled(o.output)) std::cerr << "\n";
  std::string message = res.message;
  if (res.status == RunStatus::Interrupted && output->checkpoints_written() > 0)
    message += "; checkpoint " + files.checkpoint;
  // A completed run's last checkpoint is behind its end: of no use, and easily mistaken for one.
  if (res.completed() && output->checkpoints_written() > 0)
    std::filesystem::remove(files.checkpoint);

  // --- results ---
  TwodRunReport report;
  MeasureOptions measure_opt;
  measure_opt.mode = o.mode;
  measure_opt.seeded_phase_speed = seeded.phase_speed;
  report.measured = measure(res.series, measure_opt);
  report.json = twod_result_json(res, solver, base, report.measured, seeded, schedule.dt_out);
  report.json["status"] = run_status_name(res.status);
  report.json["warnings"] = warnings;
  report.json["message"] = message;
  report.json["eta_max"] = mo.settings.eta_max;
  report.json["extrapolated"] = nullptr;  // without --extrapolate
  if (mo.extrapolate) {
    report.extrapolation = extrapolate(o, mo, schedule.dt_out, report.measured, res, seeded, stop);
    report.json["extrapolated"] = extrapolation_json(*report.extrapolation, seeded.growth_rate);
  }
  output->finish(res.series, run_status_name(res.status), message, report.json.dump());
  report.series = res.series;
  report.status = res.status;
  report.message = message;
  report.Lz = Lz;
  return report;
}

}  // namespace granbench::cli

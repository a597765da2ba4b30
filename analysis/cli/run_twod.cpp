// granbench run --model twod: the §7 rollwave (or any periodic chute flow) with the full 2D
// incompressible mu(I) equations (2.9)-(2.11) and a VOF free surface (twod/).
//
//   granbench run --model twod --angle 28.5 --h0 0.004 --a0 2e-4 --Lx 0.08 --nx 256 --nz 64
//                 --t-end 10 --out roll.h5          (roll.h5 + roll.xdmf for ParaView)
//   granbench run --model twod --restart roll.checkpoint.h5 --t-end 10 ...
//
// Output: the SurfaceSeries h(x, t) (/surface), 2D snapshots (/snapshots, indexed by the XDMF
// file), the run statistics and every parameter (/parameters). The time loop is twod::run
// (twod/run.hpp). Ctrl-C or SIGTERM stops the run at its next sample, writes a checkpoint and the
// outputs, then exits with code 130; a diverging run reports time, place and quantity, saves what
// it computed and exits with code 3; any other failure in the time loop saves what it computed
// and exits with code 1.
#include "run_twod.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "checkpoint.hpp"
#include "commands.hpp"
#include "diagnostics.hpp"
#include "eigenmode_seed.hpp"
#include "hdf5_file.hpp"
#include "initial_state.hpp"
#include "linear2d_eigenmode.hpp"
#include "measurement_json.hpp"
#include "output.hpp"
#include "run.hpp"
#include "solver.hpp"
#include "steady_state.hpp"
#include "surface_measurement.hpp"
#include "wave_speed.hpp"

namespace granbench::cli {

namespace {

std::string replace_extension(const std::string& path, const std::string& ext) {
  return std::filesystem::path(path).replace_extension(ext).string();
}

}  // namespace

void add_twod_options(CLI::App& app, TwodOptions& o) {
  app.add_option("--nz", o.nz, "twod: cells along z, in [4, 4096]")
      ->check(CLI::Range(4, 4096))
      ->capture_default_str();
  app.add_option("--Lz", o.Lz, "twod: domain height [m], > h0 + a0; default about 2 h0 with h0 mid-cell")
      ->check(positive());
  app.add_option("--eta-max", o.eta_max, "twod: cap on the granular viscosity [Pa s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--eta-min", o.eta_min, "twod: floor on the granular viscosity [Pa s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--D-min", o.D_min, "twod: floor on |D| [1/s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--rho-light", o.rho_light, "twod: light-fluid density [kg/m^3], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--eta-light", o.eta_light, "twod: light-fluid viscosity [Pa s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--mixing", o.mixing, "twod: viscosity in interface cells {arithmetic,harmonic}")
      ->check(one_of({"arithmetic", "harmonic"}))
      ->capture_default_str();
  app.add_option("--cfl", o.cfl, "twod: Courant number per direction, in (0, 0.5)")
      ->check(open_range(0.0, 0.5))
      ->capture_default_str();
  app.add_option("--viscosity-passes", o.viscosity_passes,
                 "twod: predictor-projection passes per step, eta from the previous pass, in [1, 4] "
                 "(1: one solve, second order in time through the stress tangent; more passes "
                 "cost n times as much, docs/twod-validation.md)")
      ->check(CLI::Range(1, 4))
      ->capture_default_str();
  app.add_option("--dt-max", o.dt_max, "twod: largest time step [s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--tolerance", o.tolerance, "twod: relative residual of the linear solves, in (0, 1e-3)")
      ->check(open_range(0.0, 1e-3))
      ->capture_default_str();
  app.add_option("--dt-snapshot", o.dt_snapshot,
                 "twod: interval of the 2D field snapshots [s], > 0; default t_end/10")
      ->check(positive());
  app.add_option("--checkpoint", o.checkpoint,
                 "twod: checkpoint written on SIGINT/SIGTERM; default <out>.checkpoint.h5");
  app.add_option("--restart", o.restart, "twod: continue from this checkpoint file")
      ->check(CLI::ExistingFile);
}

TwodRunReport run_twod_model(const RunOptions& o, const TwodOptions& mo,
                             const std::atomic<bool>* stop) {
  using namespace granbench::twod;
  // --- parameters (validated before anything is written) ---
  if (o.noise != 0.0) throw UsageError("--noise: not available for --model twod; valid value 0");
  const MuCurve curve = o.flow.make_curve();
  const double zeta = degrees_to_radians(o.flow.angle_deg);
  SteadyState base;
  try {
    base = steady_state(curve, zeta, o.flow.h0);
  } catch (const CurveRangeError& e) {
    throw UsageError(std::string("--angle: ") + e.what());
  }
  const double Lz = mo.Lz > 0.0 ? mo.Lz : twod::mid_cell_domain_height(o.flow.h0, mo.nz);
  if (!(Lz > o.flow.h0 + o.a0))
    throw UsageError("--Lz: " + std::to_string(Lz) + " out of range; valid range (h0 + a0, inf)");
  if (!(mo.eta_min < mo.eta_max))
    throw UsageError("--eta-min: must be below --eta-max (" + std::to_string(mo.eta_max) + ")");
  SolverParams params;
  params.zeta = zeta;
  params.rheology.material = o.flow.material;
  params.rheology.curve = curve.kind();
  params.rheology.h0_for_curve = o.flow.h0;
  params.rheology.eta_max = mo.eta_max;
  params.rheology.eta_min = mo.eta_min;
  params.rheology.D_min = mo.D_min;
  params.rheology.rho_light = mo.rho_light;
  params.rheology.eta_light = mo.eta_light;
  params.rheology.mixing =
      mo.mixing == "harmonic" ? ViscosityMixing::Harmonic : ViscosityMixing::Arithmetic;
  params.cfl = mo.cfl;
  params.viscosity_passes = mo.viscosity_passes;
  params.dt_max = mo.dt_max;
  params.solver_tolerance = mo.tolerance;

  std::optional<Checkpoint> restart;
  if (!mo.restart.empty()) {
    try {
      restart = read_checkpoint(mo.restart);
    } catch (const std::exception& e) {
      throw UsageError(std::string("--restart: ") + e.what());
    }
    if (restart->grid.nx != int(o.nx) || restart->grid.nz != mo.nz ||
        std::abs(restart->grid.Lx - o.Lx) > 1e-12 * o.Lx || std::abs(restart->grid.Lz - Lz) > 1e-12 * Lz)
      throw UsageError("--restart: the checkpoint's grid (" + std::to_string(restart->grid.nx) + " x " +
                       std::to_string(restart->grid.nz) + ") differs from --nx/--nz/--Lx/--Lz");
    if (!(restart->state.t < o.t_end))
      throw UsageError("--t-end: must exceed the checkpoint's time " + std::to_string(restart->state.t));
  }
  const Grid grid(int(o.nx), mo.nz, o.Lx, Lz);
  const double wavelength = o.Lx / o.mode;
  // The samples and snapshots lie on the grids k dt_out and j dt_snapshot from t = 0
  // (twod/run.hpp), so a restart with the same options continues the first run's grids.
  RunSchedule schedule;
  schedule.t_end = o.t_end;
  schedule.dt_out =
      o.dt_out > 0.0 ? o.dt_out : std::min(0.01, wavelength / (8.0 * 2.0 * base.u_surface));
  schedule.dt_snapshot = mo.dt_snapshot > 0.0 ? mo.dt_snapshot : o.t_end / 10.0;
  const std::string checkpoint_path =
      !mo.checkpoint.empty() ? mo.checkpoint
      : !o.output.out.empty() ? replace_extension(o.output.out, ".checkpoint.h5")
                              : std::string("twod.checkpoint.h5");

  // --- initial state ---
  // sine: (7.2); eigenmode: the least-stable surface mode of the exact 2D linear theory at this
  // wavelength, amplitude a0 (analysis/comparison/eigenmode_seed.hpp).
  // The surface mode's phase speed also identifies the seeded wave among the waves the
  // measurement separates (a sine start projects mostly onto it, too).
  std::optional<linear2d::Eigenmode> eigenmode;
  try {
    eigenmode = linear2d::surface_eigenmode(base, curve, wavelength);
  } catch (const std::exception&) {
    if (o.init == "eigenmode") throw;
  }
  const double seeded_speed = eigenmode ? eigenmode->phase_speed() : NAN;
  const InitialCondition ic = o.init == "eigenmode" ? eigenmode_initial_condition(*eigenmode, o.a0)
                                                    : perturbed_bagnold(base, o.a0, wavelength);
  Solver solver(grid, params, restart ? restart->state : make_initial_state(grid, ic, params));
  SurfaceSeries series = SurfaceSeries::uniform_grid(o.Lx, o.nx, o.flow.h0);
  if (restart) {
    solver.resume(restart->steps, restart->dt_last, restart->initial_volume);
    solver.set_warm_start(restart->warm_start);
    if (restart->series.nt() > 0) series = restart->series;
  }

  std::unique_ptr<H5Writer> h5;
  std::unique_ptr<SnapshotWriter> snaps;
  if (!o.output.out.empty()) {
    h5 = std::make_unique<H5Writer>(o.output.out);
    snaps = std::make_unique<SnapshotWriter>(
        *h5, std::filesystem::path(o.output.out).filename().string(),
        replace_extension(o.output.out, ".xdmf"), grid);
  }

  // --- time loop (twod/run.hpp) ---
  const bool progress = progress_enabled(o.output);
  const auto wall0 = std::chrono::steady_clock::now();
  auto wall = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count(); };
  double last_report = 0.0;
  RunHooks hooks;
  hooks.stop = stop;
  hooks.sample = [&](const Solver& s, const SurfaceSeries&) {
    if (!progress || wall() - last_report <= 1.0) return;
    last_report = wall();
    std::cerr << "\r  t = " << std::fixed << std::setprecision(4) << s.state().t << " / " << o.t_end
              << " s, step " << s.statistics().steps << ", dt " << std::scientific
              << std::setprecision(2) << s.statistics().dt_last << " s, wall " << std::fixed
              << std::setprecision(0) << last_report << " s    " << std::flush;
  };
  // Set also without --out: the snapshot times are part of the step sequence, and a run should
  // not change with whether its fields are written.
  hooks.snapshot = [&](const Solver& s) {
    if (snaps) snaps->write(s);
  };
  hooks.checkpoint = [&](const Solver& s, const SurfaceSeries& kept) {
    write_checkpoint(checkpoint_path, s, kept);
  };
  const RunResult res = twod::run(solver, std::move(series), schedule, hooks);
  if (progress) std::cerr << "\n";
  const std::string status = run_status_name(res.status);
  std::string message = res.message;
  if (res.status == RunStatus::Interrupted) message += "; checkpoint " + checkpoint_path;

  // --- results ---
  const SurfaceSeries& kept = res.series;
  const RunStatistics st = solver.statistics();
  MeasureOptions measure_opt;
  measure_opt.mode = o.mode;
  measure_opt.seeded_phase_speed = seeded_speed;
  const SurfaceMeasurement growth = measure_surface_series(kept, measure_opt);
  std::optional<WaveSpeed> wave;
  if (kept.nt() >= 8) {
    try {
      wave = wave_speed(kept, 0.5 * kept.t.back(), kept.t.back());
    } catch (const std::invalid_argument&) {
    }
  }
  const auto last_h = kept.h_at(kept.nt() - 1);
  double h_mean = 0.0;
  for (double v : last_h) h_mean += v / double(last_h.size());
  nlohmann::json j = {
      {"model", "twod"},
      {"status", status},
      {"message", message},
      {"t_reached", solver.state().t},
      {"steps", st.steps},
      {"viscous_iterations", st.viscous_iterations},
      {"projection_iterations", st.projection_iterations},
      {"wall_seconds", wall()},
      {"cell_updates_per_second", double(st.steps) * grid.cells() / std::max(wall(), 1e-9)},
      {"mass_error", st.mass_error()},
      {"vof_clipped_volume", st.clipped_volume / std::max(st.initial_volume, 1e-300)},
      {"max_divergence", st.max_divergence},
      {"dt_min", st.dt_min},
      {"dt_max", st.dt_max},
      {"h_mean", h_mean},
      {"flux", mean_flux(grid, solver.state())},
      {"growth_rate", number_or_null(growth.growth_rate)},
      {"phase_speed", number_or_null(growth.phase_speed)},
      {"modes", modes_json(growth)},
      {"phase_speed_theory", number_or_null(seeded_speed)},
      {"growth_window", window_json(growth)},
      {"growth_window_found", growth.found()},
      {"growth_fit_residual", number_or_null(growth.relative_residual)},
      {"growth_note", growth.reason},
      {"growth_data_note", growth.note},
      {"wave_speed", wave ? number_or_null(wave->speed) : nullptr},
      {"wave_speed_spread", wave ? number_or_null(wave->spread) : nullptr},
      {"I_range", std::isfinite(res.I_min) ? nlohmann::json{res.I_min, res.I_max} : nullptr},
      {"illposed_fraction", res.last.illposed_fraction},
      {"illposed_fraction_max", res.illposed_fraction_max},
      {"eta_max", mo.eta_max},
      {"dt_out", schedule.dt_out},
      {"F", base.Fr},
      {"u_mean", base.u_mean}};

  if (h5) {
    write_surface_series(*h5, "/surface", kept);
    write_parameters(*h5, "/parameters", grid, params);
    h5->attribute("/", "model", "twod");
    h5->attribute("/", "status", status);
    h5->attribute("/", "message", message);
    h5->attribute("/", "a0", o.a0);
    h5->attribute("/", "h0", o.flow.h0);
    h5->attribute("/", "t_end", o.t_end);
    h5->attribute("/", "results_json", j.dump());
    snaps->finish();
    h5->close();
  }
  TwodRunReport report;
  report.json = std::move(j);
  report.status = res.status;
  report.message = message;
  report.growth = growth;
  report.Lz = Lz;
  return report;
}

void run_twod(const RunOptions& o, const TwodOptions& mo) {
  const InterruptGuard guard(InterruptGuard::Signals::IntAndTerm);
  const TwodRunReport r = run_twod_model(o, mo, guard.flag());
  const nlohmann::json& j = r.json;
  if (o.output.json) {
    print_json(j);
  } else {
    auto show = [&j](const char* key) { return j[key].is_null() ? std::string("-") : j[key].dump(); };
    const SurfaceMeasurement& growth = r.growth;
    std::cout << "twod run (" << j["status"].get<std::string>() << "), " << o.flow.curve
              << " curve, angle " << o.flow.angle_deg << " deg, h0 = " << o.flow.h0 << " m, "
              << o.nx << " x " << mo.nz << " cells on " << o.Lx << " x " << r.Lz << " m\n"
              << "  t reached        " << j["t_reached"].get<double>() << " s in "
              << j["wall_seconds"].get<double>() << " s wall, " << j["steps"].get<long>()
              << " steps\n"
              << "  mass error       " << j["mass_error"].get<double>() << " (relative)\n"
              << "  h mean, flux     " << j["h_mean"].get<double>() << " m, "
              << j["flux"].get<double>() << " m^2/s\n"
              << "  growth rate      " << show("growth_rate") << " 1/s, phase speed "
              << show("phase_speed") << " m/s"
              << (growth.found() ? "" : "  (not measured: " + growth.reason + ")") << "\n";
    for (std::size_t i = 0; i < growth.modes.size(); ++i)
      if (i != growth.seeded)
        std::cout << "  other wave       growth " << growth.modes[i].growth_rate << " 1/s, speed "
                  << growth.modes[i].phase_speed << " m/s, amplitude "
                  << growth.modes[i].amplitude * 1e3 << " mm (seeded "
                  << growth.modes[growth.seeded].amplitude * 1e3 << " mm)\n";
    const auto& I = j["I_range"];
    std::cout << "  wave speed       " << show("wave_speed") << " m/s (second half of the run)\n"
              << "  I range          "
              << (I.is_null() ? std::string("-")
                              : std::to_string(I[0].get<double>()) + " .. " +
                                    std::to_string(I[1].get<double>()))
              << ", ill-posed fraction " << j["illposed_fraction"].get<double>() << " (max "
              << j["illposed_fraction_max"].get<double>() << ")\n";
  }
  throw_unless_completed(r);
}

void throw_unless_completed(const TwodRunReport& r) {
  switch (r.status) {
    case twod::RunStatus::Completed:
      return;
    case twod::RunStatus::Interrupted:
      throw CommandFailed(r.message + "; the samples computed so far were kept", 130);
    case twod::RunStatus::Diverged:
      throw CommandFailed(r.message, 3);
    case twod::RunStatus::Failed:
      throw CommandFailed(r.message + "; the samples computed so far were kept", 1);
  }
}

}  // namespace granbench::cli

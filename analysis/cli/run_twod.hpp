// `granbench run --model twod`: the 2D two-phase mu(I) solver's own options and entry point
// (run_twod.cpp). The options shared by every model (angle, h0, curve, Lx, nx, a0, t_end, ...)
// are in RunOptions (run_model.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <atomic>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "analysis/cli/run_model.hpp"
#include "analysis/comparison/twod_extrapolation.hpp"
#include "analysis/comparison/twod_settings.hpp"
#include "analysis/spectral/measurement.hpp"
#include "common/steady_state.hpp"
#include "twod/parameters.hpp"
#include "twod/run.hpp"
#include "twod/solver.hpp"
#include "twod/viscosity_mixing.hpp"

namespace granbench::cli {

struct TwodOptions {
  // The solver settings, shared with compare and sweep (analysis/comparison/twod_settings.hpp);
  // settings.nx (the preset's along 8 cm) gives --nx its default (cells_along; the run's grid is
  // RunOptions::nx), settings.Lz_over_h0 follows --Lz.
  TwodSettings settings = [] {
    TwodSettings s;
    s.nz = 64;
    return s;
  }();
  // domain height [m]; 0: ~(1 + settings.light_layer_over_h0) h0, h0 mid-cell
  // (mid_cell_domain_height)
  double Lz = 0.0;
  std::string mixing = twod::viscosity_mixing_name(twod::Rheology{}.mixing);  // --mixing's text
  std::string momentum_transport =  // --momentum-transport's text
      twod::SolverParams{}.consistent_momentum ? "consistent" : "velocity";
  double dt_snapshot = 0.0;  // interval of the 2D field snapshots [s]; 0: t_end/10
  std::string checkpoint;  // written on schedule and on SIGINT/SIGTERM; default <out>.checkpoint.h5
  double checkpoint_every = 1.0;  // simulated time between checkpoints [s]; 0: only at a stop
  std::string restart;            // continue from this checkpoint
  // `run` only: after the run, the same wave on half the cells across the layer, and its growth
  // extrapolated to cells of no height (analysis/comparison/twod_extrapolation.hpp)
  bool extrapolate = false;
};
void add_twod_options(CLI::App& app, TwodOptions& o);  // twod_options.cpp
// --cfl, the 2D time step's Courant number, for run, compare and sweep alike (twod_options.cpp)
void add_twod_cfl_option(CLI::App& app, double& cfl);
// How the default 2D grid refines across the layer, for the help of compare's and sweep's
// --resolution and run's --nz: "for a wave under 7.5 h0 up to 2x the cells across the layer, ...",
// from the rules' own constants (TwodSettings, grid_preset), so the three texts cannot drift.
std::string twod_refinement_help();  // twod_options.cpp
// --extrapolate, an option of `run` alone (twod_options.cpp): the rollwave cases saturate, where
// the deficit law of a linear wave does not hold.
void add_twod_extrapolate_option(CLI::App& app, TwodOptions& o);

// The chute case of `run`'s options (the flow, the domain length, the seed and run length).
ChuteCase chute_case(const RunOptions& run);
// The 2D settings of these options as compare and sweep would hold them (nx from --nx, the
// domain height from --Lz, or 0 for the solver's mid-cell height): the run's, and through
// half_cells_across those of an extrapolation's second run.
TwodSettings twod_run_settings(const RunOptions& run, const TwodOptions& model);
// The solver parameters of these options (twod_options.cpp), through the one builder of
// twod_settings.hpp; UsageError naming the option when they are inconsistent. `Lz` receives the
// domain height used.
twod::SolverParams twod_run_params(const RunOptions& run, const TwodOptions& model, double& Lz);

// One 2D run as `granbench run --model twod --json` reports it.
struct TwodRunReport {
  nlohmann::json json;  // the keys printed by --json
  twod::RunStatus status = twod::RunStatus::Completed;
  std::string message;   // why it stopped early (with the checkpoint's path)
  Measurement measured;  // the measurement behind json's growth keys
  SurfaceSeries series;  // h(x, t) of the whole run (a restart's included)
  double Lz = 0.0;       // the domain height used [m]
  // --extrapolate: the run on half the cells across the layer and the extrapolated growth
  std::optional<TwodExtrapolation> extrapolation;
};

// Validates the options and paths (UsageError, before any work), runs the 2D model until t_end
// or *stop, writes --out (+ .xdmf) and the checkpoints (twod/run_output.hpp): on the
// --checkpoint-every schedule, removed when the run completes, and at a stop. Prints only the
// progress line on stderr. Used by `run` and by `case` (the rollwave cases), so both run the
// same code in this process.
TwodRunReport run_twod_model(const RunOptions& run, const TwodOptions& model,
                             const std::atomic<bool>* stop);

// The progress line on stderr (at most once a wall second), or an empty hook when `show` is
// false; and the keys of a 2D run's JSON that come from the run itself (twod_report.cpp).
std::function<void(const twod::Solver&, const SurfaceSeries&)> twod_progress_line(
    const RunOptions& run, bool show);
// The seeded wave's exact 2D linear theory (the surface mode, stress-free surface), NaN where it
// was not found: the run's JSON and table show it beside the measurement.
struct SeededTheory {
  double growth_rate = NAN, phase_speed = NAN;
};
nlohmann::json twod_result_json(const twod::RunResult& result, const twod::Solver& solver,
                                const SteadyState& base, const Measurement& measured,
                                SeededTheory seeded, double dt_out);

// `granbench run --model twod`: run_twod_model under Ctrl-C and SIGTERM handling; prints the
// table or JSON (twod_report.cpp). Throws CommandFailed after saving what was computed when
// interrupted (exit 130 or 143, with a checkpoint), diverged or failed (exit 3).
void run_twod(const RunOptions& run, const TwodOptions& model);

// The exit of a finished 2D run: nothing when completed, else CommandFailed with the code of
// the failure policy (failure_policy.hpp); `guard` tells SIGINT from SIGTERM.
void throw_unless_completed(const TwodRunReport& report, const InterruptGuard& guard);

}  // namespace granbench::cli

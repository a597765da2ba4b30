// Shared pieces of the granbench command line: the error type that maps to exit code 2 with one
// line naming the option and its valid range, validators, and the options every model-facing
// subcommand shares (material, curve, slope, depth). Parsing and validation only; no physics.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>

#include "analysis/comparison/chute_case.hpp"
#include "analysis/spectral/wave_speed.hpp"
#include "common/material.hpp"
#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"

namespace granbench::cli {

// Bad user input discovered after parsing: printed as "granbench: error: <what>", exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Validators whose messages name the valid range.
CLI::Validator positive();                             // (0, inf)
CLI::Validator non_negative();                         // [0, inf)
CLI::Validator open_range(double lo, double hi);       // (lo, hi)
CLI::Validator closed_range(double lo, double hi);     // [lo, hi]
CLI::Validator half_open_range(double lo, double hi);  // [lo, hi)
// A whole number in [lo, hi]; the message shows `shown` instead when given (a bound that
// depends on another option, as [1, nx/2]).
CLI::Validator count_range(long lo, long hi, const std::string& shown = "");
CLI::Validator one_of(const std::vector<std::string>& values);  // {a,b,...}

// Options shared by wellposed/steady/dispersion/run/sweep/compare.
struct FlowOptions {
  std::string curve = "regularised";
  double angle_deg = 28.5;
  double h0 = 4e-3;
  Material material;

  CurveKind curve_kind() const;
  MuCurve make_curve() const;
  // The steady state of these options; a slope with no steady flow is a UsageError on --angle.
  SteadyState steady() const;
  // The chute case of this flow on a domain of length Lx [m] (the seed and run length at their
  // defaults); `run`, `compare` and `sweep` start from it.
  ChuteCase chute(double Lx) const;
};
// add_slope=false for subcommands with no slope (wellposed).
void add_flow_options(CLI::App& app, FlowOptions& o, bool add_slope = true);

// Common output options.
struct OutputOptions {
  bool json = false;
  std::string out;   // HDF5 path, empty for none
  std::string plot;  // PNG path, empty for none
  bool quiet = false;
};
void add_output_options(CLI::App& app, OutputOptions& o, bool with_plot = true);

// --threads N (integer >= 1): the threads of the 2D solver for this command, set on the
// command's thread as soon as the option is parsed (twod/parallel.hpp); without it,
// OMP_NUM_THREADS or all cores. Results do not depend on it.
void add_threads_option(CLI::App& app);

// Print JSON (pretty) to stdout; nulls for non-finite numbers.
void print_json(const nlohmann::json& j);
nlohmann::json number_or_null(double v);
// Run a plotting script from analysis/plots with Debian's python3: script data.h5 out.png [args].
void run_plot_script(const std::string& script, const std::string& h5, const std::string& png,
                     const std::string& extra_args = "");
// Show progress only on a terminal and without --quiet (docs/design.md).
bool progress_enabled(const OutputOptions& o);

// What a run's wave speed (Measurement::wave, wave_speed.hpp) is, for the text reports:
// "(phase speed of Fourier mode 1 over the last fifth of the run, t = 8 .. 10 s)", or why it was
// not measured.
std::string wave_speed_note(const std::optional<WaveSpeed>& w);

// "ETA 3 min 12 s": the wall time left if the run keeps its pace so far, from the wall seconds
// since it started and the simulated times (t_start, t, t_end); "ETA -" before any progress.
std::string eta_text(double wall_seconds, double t_start, double t, double t_end);

}  // namespace granbench::cli

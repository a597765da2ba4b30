// `granbench run` and `granbench sweep`: the options every model shares, the model choice, and
// the per-model entry points. Each model has one file, run_<model>.cpp, that builds its solver
// from these options and returns the result as JSON (keys shared by all models: steps,
// wall_seconds, mass_error, h_mean, flux, growth_rate, phase_speed, wave_speed, wave_mode).
//
// Adding a model: add an enumerator to Model, its name to model_names(), a run_<model>.cpp with
// its own options struct, and one case in the dispatch of cmd_run.cpp.
#pragma once

#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/cli/cli_common.hpp"
#include "common/failure_policy.hpp"
#include "depthavg/params.hpp"

namespace granbench::cli {

enum class Model { DepthAvg, TwoD };
std::vector<std::string> model_names();
Model parse_model(const std::string& name);

// Model-independent options of `granbench run`.
struct RunOptions {
  FlowOptions flow;
  OutputOptions output;
  std::string model = "depthavg";
  double Lx = 0.08;           // domain length [m]
  std::size_t nx = 256;       // cells along x
  double a0 = 2e-4;           // perturbation amplitude [m] (7.2)
  int mode = 1;               // wavelengths of the perturbation in the domain
  std::string init = "sine";  // sine (7.2) or eigenmode (7.10)
  double noise = 0.0;         // random height noise, fraction of h0
  std::uint64_t seed = 1;
  double t_end = 10.0;  // [s]
  double dt_out = 0.0;  // sampling interval [s]; 0: automatic
  double rtol = 1e-6;
  double atol = 1e-10;
  int bdf_order = 0;  // CVODE's BDF order limit; 0: 2 co-moving, 5 in the lab frame
};
void add_run_options(CLI::App& app, RunOptions& o);

// Depth-averaged model's own options.
struct DepthAvgOptions {
  std::string chi = "1";  // shape factor: 1, bagnold (5/4) or a number >= 1
  // Slope reconstruction: a name of depthavg::parse_reconstruction, or "auto" (limiter_for_seed)
  std::string limiter = "auto";
  // Computational frame: 0 (lab), linear (the seeded mode's (7.11) phase speed), or a speed
  // [m/s]. Co-moving by default: a wave that travels at about that speed is nearly steady in it,
  // so CVODE takes ~20 times fewer steps; the output is in the lab frame either way.
  std::string frame_speed = "linear";
};
void add_depthavg_options(CLI::App& app, DepthAvgOptions& o);
// The reconstruction of --limiter: the named one, or for "auto" the rule of compare and sweep
// (DepthAvgSettings::limited_where_it_saturates): central slopes, which measure the linear regime
// cleanly, while the seed stays below the measurement's linear bound; van Albada's limiter where
// it grows past it before the run's end (a wave with fronts, where central slopes oscillate).
depthavg::Reconstruction limiter_for_seed(const std::string& limiter, bool seed_saturates);
// Shape factor from its option text; UsageError naming --chi otherwise.
double parse_chi(const std::string& text);
// Frame speed from its option text ('linear': `linear_speed`); UsageError naming --frame-speed.
double parse_frame_speed(const std::string& text, double linear_speed);

// InterruptGuard (Ctrl-C and SIGTERM keep what was computed) is part of the failure policy.

// Runs the depth-averaged model; prints the table or JSON, writes --out (checked before any
// work). Throws CommandFailed (after writing what was computed) when interrupted (exit 130 on
// SIGINT, 143 on SIGTERM) or diverged or failed (exit 3).
void run_depthavg(const RunOptions& run, const DepthAvgOptions& model);

// The checks of `run` that span several options (a0 below h0, mode at most nx/2): UsageError.
void check_run_options(const RunOptions& run);

}  // namespace granbench::cli

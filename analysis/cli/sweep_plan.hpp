// `granbench sweep`'s options and what they make of a sweep: the SweepSpec the engine runs, the
// JSON keys and the table's title (cmd_sweep.cpp registers the subcommand with these). Kept apart
// from the command so that a test can enumerate the registered options and check that every one
// that changes a result is stored with the points (sweep.hpp: stored_settings), or refused for a
// model it does not apply to, or listed here as changing no result.
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/run_model.hpp"
#include "analysis/comparison/sweep.hpp"

namespace granbench::cli {

struct SweepOptions {
  FlowOptions flow;
  OutputOptions output;
  DepthAvgOptions depthavg;
  std::string model = "depthavg";
  std::string Lx = "0.03:0.4:12";
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  std::size_t nx = 192;
  double tolerance = 1e-6;
  double t_end = 0.0;
  std::string resolution = "default";  // 2D grid of --model twod|both (32 cells per h0)
  int viscosity_passes = 1;            // of --model twod|both
  double twod_frame = 0.5;             // of --model twod|both: TwodSettings::frame_fraction
  double cfl = TwodSettings{}.cfl;     // of --model twod|both: the 2D time step's Courant number
  bool extrapolate = false;            // of --model twod|both: SweepSpec::twod_extrapolate
};

// Registers the options on `app` (the sweep subcommand).
void add_sweep_options(CLI::App& app, SweepOptions& o);

struct SweepPlan {
  SweepSpec spec;
  nlohmann::json settings;  // the command's own keys for the JSON
  std::string title;        // the table's first line
  // The 2D points' physics warnings (physics_warnings.hpp; the grid's, the shortest wave's, and
  // with add_growth_accuracy_warnings those of small growth rates), printed once the sweep's checks
  // have passed and listed under "warnings" in the JSON.
  std::vector<std::string> warnings;
};
// After parsing `app` (for which options were given). UsageError for an option that does not
// apply to the chosen --model, or for a bad value.
SweepPlan plan_sweep(const SweepOptions& o, const CLI::App& app);

// Adds to the plan's warnings (and its JSON settings) every 2D point whose exact 2D growth rate is
// small against the deficit its grid is expected to carry (twod_growth_accuracy_warning), named by
// its length. Apart from plan_sweep because it solves the surface eigenmode at each length (some
// 25 ms each).
void add_growth_accuracy_warnings(const SweepOptions& o, SweepPlan& plan);

// The options that change no stored result, each with the reason: how the work is shared, where
// it goes, how it is shown, and the two that choose the points (each point is stored with its
// model and its Lx).
const std::map<std::string, std::string>& sweep_options_without_effect_on_results();

}  // namespace granbench::cli

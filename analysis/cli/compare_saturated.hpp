// `granbench compare --saturated`: both models run past saturation on the same case, and each
// saturated wave measured alike (analysis/comparison/saturated_comparison.hpp): amplitude, front
// steepness and width, wave speed, mean flux, side by side with their ratio; the two wave shapes
// overlaid in the wave's frame (HDF5 and figure). The paper's closing claim, measured: are the
// depth-averaged fronts much steeper than the 2D ones?
//
// The mode reuses compare's case and grid options; it changes three defaults, because a saturated
// wave needs the paper's start and a long run: the start is the paper's (7.2) sine with a0 = 0.2 mm
// (unless --init or --a0 is given), t_end is kSaturatedTEnd (unless --t-end is given), and the
// depth-averaged model uses the MC limiter (its saturated fronts are a few cells wide; central
// slopes ring there).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "analysis/cli/cli_common.hpp"
#include "analysis/comparison/chute_case.hpp"
#include "analysis/comparison/model_runs.hpp"

namespace granbench::cli {

// Long enough for both models to saturate at the default case (§7: 28.5 deg, h0 = 4 mm, Lx = 8 cm,
// a0 = 0.2 mm); docs/comparison.md shows the amplitude against time.
inline constexpr double kSaturatedTEnd = 10.0;   // [s]
inline constexpr double kSaturatedWindow = 1.0;  // [s]
inline constexpr double kSaturatedA0 = 2e-4;     // [m], the paper's

struct SaturatedOptions {
  bool enabled = false;
  double window = kSaturatedWindow;  // the measured end of each run [s]
  // compare's options whose defaults the mode replaces when they were not given
  const CLI::Option* t_end = nullptr;
  const CLI::Option* a0 = nullptr;
  const CLI::Option* init = nullptr;
  const CLI::Option* paper = nullptr;
};

// --saturated and --window on compare's subcommand; call after compare's own options.
void add_saturated_options(CLI::App& compare, SaturatedOptions& s);

// The mode, on the case and settings compare resolved from its options (before its own output
// checks); `warnings` are compare's physics warnings for the 2D grid.
void run_compare_saturated(ChuteCase chute, DepthAvgSettings depthavg, const TwodSettings& twod,
                           const OutputOptions& output, const SaturatedOptions& s,
                           const std::vector<std::string>& warnings);

}  // namespace granbench::cli

// What `granbench run --model depthavg` prints and writes (depthavg_report.cpp); it measures with
// measure().
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/cli/run_model.hpp"
#include "analysis/spectral/measurement.hpp"
#include "common/steady_state.hpp"
#include "depthavg/solver.hpp"

namespace granbench::cli {

// The table (or, with --json, the JSON `j`) of a depth-averaged run on stdout.
void print_depthavg_run(const RunOptions& o, const nlohmann::json& j, const Measurement& m);
// --out: the SurfaceSeries, every input and the run's JSON `j` (which holds dt_out and status).
void write_depthavg_run(const RunOptions& o, const DepthAvgOptions& mo,
                        const depthavg::SpaceParams& space, const SteadyState& base,
                        const depthavg::RunResult& r, const nlohmann::json& j);

}  // namespace granbench::cli

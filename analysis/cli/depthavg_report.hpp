// What `granbench run --model depthavg` prints (depthavg_report.cpp); it measures with measure().
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/cli/run_model.hpp"
#include "analysis/spectral/measurement.hpp"

namespace granbench::cli {

// The table (or, with --json, the JSON `j`) of a depth-averaged run on stdout.
void print_depthavg_run(const RunOptions& o, const nlohmann::json& j, const Measurement& m);

}  // namespace granbench::cli

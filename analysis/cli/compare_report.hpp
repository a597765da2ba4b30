// What `granbench compare` reports (compare_report.cpp): the JSON of one model's run and
// measurement, and the side-by-side table.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/comparison/compare.hpp"
#include "common/failure_policy.hpp"

namespace granbench::cli {

nlohmann::json model_json(const ModelRun& run, const Measurement& measurement);
void print_table(const Comparison& c);
// The whole of `compare --json`: the theories, each model's run and measurement, the warnings
// and the files written.
nlohmann::json compare_json(const Comparison& c, int viscosity_passes,
                            const std::vector<std::string>& warnings, const std::string& h5,
                            const std::string& png);
// The exit of compare and compare --saturated (failure_policy.hpp): nothing when both runs
// completed, else CommandFailed naming the model, its status and where the data up to then were
// written.
void throw_unless_both_completed(const ModelRun& depthavg, const ModelRun& twod,
                                 const InterruptGuard& guard, const std::string& h5);

}  // namespace granbench::cli

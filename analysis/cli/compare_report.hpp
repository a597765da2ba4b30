// What `granbench compare` reports (compare_report.cpp): the JSON of one model's run and
// measurement, and the side-by-side table.
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/comparison/compare.hpp"

namespace granbench::cli {

nlohmann::json model_json(const ModelRun& run, const Measurement& measurement);
void print_table(const Comparison& c);

}  // namespace granbench::cli

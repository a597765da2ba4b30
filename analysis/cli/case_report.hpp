// What `granbench case` prints without --json (case_report.cpp): the runs of a case, the grid
// dependence of the layer cases, the rollwave's result, and the files written.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace granbench::cli {

void print_summary(const std::string& kind, const nlohmann::json& j);

}  // namespace granbench::cli

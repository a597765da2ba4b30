// What `granbench sweep` reports (sweep_models.cpp): each point's JSON, the whole sweep's JSON
// and the table, with every measured-against-theory error relative to the point's own model's
// theory and null (never a number) where a point has no measurement.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/comparison/sweep.hpp"

namespace granbench::cli {

nlohmann::json point_json(const SweepPoint& p);
// `settings` (the sweep's options) with the run's counts, the worst growth error over the
// completed unstable points and every point.
nlohmann::json sweep_json(const std::vector<SweepPoint>& points, const nlohmann::json& settings,
                          unsigned jobs, int ranks, double wall_seconds);
void print_table(const std::vector<SweepPoint>& points, const std::string& title);

}  // namespace granbench::cli

// How compare and `run --model twod` report a 2D growth rate extrapolated to cells of no height
// (analysis/comparison/twod_extrapolation.hpp): one JSON object and one refusal for both.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/comparison/twod_extrapolation.hpp"

namespace granbench::cli {

// {growth_rate, growth_rate_bounds, growth_relative_error (against theory_growth; null when it
// is NaN), growth_rate_half_cells, half_cells_grid, dz_ratio, wall_seconds, steps}, or
// {growth_rate: null, reason}.
nlohmann::json extrapolation_json(const TwodExtrapolation& e, double theory_growth);

// The cells across the layer (a multiple of 16) whose half lies in the deficit law's range, for
// a domain of this height: what a refusal of --extrapolate suggests.
int nz_for_extrapolation(double domain_height, double h0);

// The start of that refusal's message: "--extrapolate: half of this grid's cells across the
// layer, n per h0, lie below the deficit law's range; valid with at least 15 per h0 there".
std::string too_few_cells_to_extrapolate(double half_cells_per_depth);

// What the small-growth warning adds where --extrapolate was not given and would apply: "; or
// give --extrapolate, which runs <subject> again on half the cells across the layer and ...".
std::string extrapolate_suggestion(const std::string& subject);

}  // namespace granbench::cli

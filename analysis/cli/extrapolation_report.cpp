// The report of an extrapolated 2D growth rate; see extrapolation_report.hpp.
#include "analysis/cli/extrapolation_report.hpp"

#include <cmath>
#include <sstream>

#include "analysis/cli/cli_common.hpp"

namespace granbench::cli {

nlohmann::json extrapolation_json(const TwodExtrapolation& e, double theory_growth) {
  if (!e.found()) return {{"growth_rate", nullptr}, {"reason", e.reason}};
  return {{"growth_rate", e.growth.value},
          {"growth_rate_bounds", {e.growth.low, e.growth.high}},
          {"growth_relative_error",
           number_or_null((e.growth.value - theory_growth) / std::fabs(theory_growth))},
          {"growth_rate_half_cells", e.growth_rate_half_cells},
          {"half_cells_grid", {e.nx, e.nz}},
          {"dz_ratio", e.dz_ratio},
          {"wall_seconds", e.wall_seconds},
          {"steps", e.steps}};
}

int nz_for_extrapolation(double domain_height, double h0) {
  return TwodSettings::multiple_of_16(
      static_cast<int>(std::ceil(2.0 * kGrowthDeficitFewestCellsPerDepth * domain_height / h0)));
}

std::string too_few_cells_to_extrapolate(double half_cells_per_depth) {
  std::ostringstream m;
  m << "--extrapolate: half of this grid's cells across the layer, " << half_cells_per_depth
    << " per h0, lie below the deficit law's range; valid with at least "
    << kGrowthDeficitFewestCellsPerDepth << " per h0 there";
  return m.str();
}

std::string extrapolate_suggestion(const std::string& subject) {
  return "; or give --extrapolate, which runs " + subject +
         " again on half the cells across the layer and extrapolates its growth to cells of no "
         "height";
}

}  // namespace granbench::cli

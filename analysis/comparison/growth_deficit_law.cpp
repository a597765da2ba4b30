// The 2D growth rate's deficit law and its extrapolation; see growth_deficit_law.hpp.
#include "analysis/comparison/growth_deficit_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace granbench {

double expected_twod_growth_deficit(const SteadyState& base, double dz, double wavelength) {
  const double k = 2.0 * std::numbers::pi / wavelength;
  return kGrowthDeficitCoefficient * std::sqrt(base.material.g / base.h0) *
         std::pow(k * dz, kGrowthDeficitOrder);
}

ExtrapolatedGrowth extrapolate_growth_in_dz(double fine, double coarse, double dz_ratio) {
  if (!(dz_ratio > 1.0) || std::isnan(fine) || std::isnan(coarse)) return {NAN, NAN, NAN};
  // With sigma(dz) = sigma_0 - C dz^p, the two measurements give C dz^p = (fine - coarse) /
  // (r^p - 1), the fine grid's own deficit.
  auto at_order = [&](double p) { return fine + (fine - coarse) / (std::pow(dz_ratio, p) - 1.0); };
  const double a = at_order(kGrowthDeficitOrderHigh), b = at_order(kGrowthDeficitOrderLow);
  return {at_order(kGrowthDeficitOrder), std::min(a, b), std::max(a, b)};
}

}  // namespace granbench

// The 2D model's growth rate against the exact 2D theory, as a function of the cells across the
// layer: the measured law of its deficit, and the Richardson extrapolation that the law's order
// allows from two grids.
//
// On the section 7 case (28.5 degrees, h0 = 4 mm) for waves of 3.75 to 20 h0 on 15.5 to 127.5
// cells per h0, and on 30 degrees, 5 mm, 10 cm, the deficit is C sqrt(g/h0) (k dz)^1.4 with C
// between 0.15 and 0.20 (0.17 at the median), falling to 0.12 for waves of 100 h0
// (docs/twod-validation.md §3, "One law for the deficit"): the surface layer's error, set by the
// cells per wavelength across the layer. Its order is that of the surface row, where the base
// shear rate goes as the square root of the depth, not the interior's 2. Calibrated on one curve
// and two slopes: the coefficient is a guide for warnings, not a correction.
#pragma once

#include "common/steady_state.hpp"

namespace granbench {

inline constexpr double kGrowthDeficitCoefficient = 0.17;
inline constexpr double kGrowthDeficitOrder = 1.4;
// The orders observed between pairs of grids in §3's tables: 1.30 (1.5 cm, 64 -> 128 cells per
// h0), 1.38-1.40 (2 cm), 1.50 and 1.66 (8 cm, 16 -> 32 -> 64).
inline constexpr double kGrowthDeficitOrderLow = 1.3, kGrowthDeficitOrderHigh = 1.7;

// The fewest cells per h0 on which the law was measured (15.5). Below it the growth is not yet in
// the law's range: the 8 cm wave grew 1.0499 1/s on 7.5 cells per h0 and 1.0480 on 15.5, against
// 1.0891, so an extrapolation from such a grid is refused.
inline constexpr double kGrowthDeficitFewestCellsPerDepth = 15.0;

// The law's deficit [1/s] of a wave of this length [m] on cells of height dz [m].
double expected_twod_growth_deficit(const SteadyState& base, double dz, double wavelength);

// The growth rate on cells of no height, from the growth rates measured on cells of height dz
// (fine) and dz_ratio dz (coarse), both with the same error law: fine + (fine - coarse) /
// (dz_ratio^p - 1) (Richardson). `value` takes the law's order 1.4; `low` and `high` the lesser
// and greater of the values with the orders 1.3 and 1.7 at the ends of the observed range, which
// bound what the pair can tell. NaN where either growth is NaN or dz_ratio <= 1.
struct ExtrapolatedGrowth {
  double value, low, high;
};
ExtrapolatedGrowth extrapolate_growth_in_dz(double fine, double coarse, double dz_ratio);

}  // namespace granbench

// The physics warnings of a 2D run (physics_warnings.hpp): an ill-posed base state, a grid
// coarser than 32 cells per h0 and a wave shorter than 7.5 h0 on fewer cells per h0 than compare
// and sweep give it (32 refined as 7.5 h0 / wavelength) are named; a well-posed base state's 8 cm
// wave on the trusted grid gets none.
#include <gtest/gtest.h>

#include "analysis/cli/physics_warnings.hpp"
#include "common/mu_curves.hpp"

using namespace granbench;

namespace {
SteadyState section7(CurveKind kind, double angle_deg) {
  const MuCurve c(kind, Material{}, 4e-3);
  return steady_state(c, degrees_to_radians(angle_deg), 4e-3);
}
}  // namespace

TEST(PhysicsWarnings, IllPosedBaseStateAndCoarseGridAreNamed) {
  const SteadyState good = section7(CurveKind::Regularised, 28.5);
  ASSERT_TRUE(good.well_posed);
  EXPECT_TRUE(cli::twod_warnings(good, 4e-3 / 32.0, 0.08).empty());
  EXPECT_TRUE(
      cli::twod_warnings(good, 2.03 * 4e-3 / 64.0, 0.08).empty());  // the default grid, mid-cell
  const auto coarse = cli::twod_warnings(good, 4e-3 / 16.0, 0.08);
  ASSERT_EQ(coarse.size(), 1u);
  EXPECT_NE(coarse[0].find("16 cells per h0"), std::string::npos) << coarse[0];

  // Jop's curve is ill posed at high inertial number (§3): the steepest slope it allows.
  const SteadyState steep = section7(CurveKind::Jop, 29.0);
  ASSERT_FALSE(steep.well_posed) << "I_zeta " << steep.I_zeta;
  const auto w = cli::twod_warnings(steep, 4e-3 / 32.0, 0.08);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("ill posed"), std::string::npos) << w[0];
}

TEST(PhysicsWarnings, AShortWaveIsNamedBelowItsRefinedGrid) {
  const SteadyState good = section7(CurveKind::Regularised, 28.5);
  // 2 cm = 5 h0 on 64 cells (31.5 cells per h0, the surface mid-cell): named, with the 48 cells
  // per h0 that compare and sweep give it
  const auto w = cli::twod_warnings(good, 2.03 * 4e-3 / 64.0, 0.02);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("short wave (5 h0)"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("default grids put 48 cells per h0 across"), std::string::npos) << w[0];
  // 2.5 cm = 6.25 h0 needs 38.4: named on 31.5, not on compare's 80 cells (39.5 per h0)
  EXPECT_EQ(cli::twod_warnings(good, 2.03 * 4e-3 / 64.0, 0.025).size(), 1u);
  EXPECT_TRUE(cli::twod_warnings(good, 4e-3 / 39.5, 0.025).empty());
  // 3 cm = 7.5 h0 (within 5 % at 32 cells per h0) and 2 cm on compare's 96 cells: not named
  EXPECT_TRUE(cli::twod_warnings(good, 2.03 * 4e-3 / 64.0, 0.03).empty());
  EXPECT_TRUE(cli::twod_warnings(good, 4e-3 / 47.5, 0.02).empty());
}

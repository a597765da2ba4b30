// Observed order of convergence of the depth-averaged scheme (label `convergence`): the errors of
// the measured growth rate and phase speed of the seeded mode (7.10) against (7.11) fall at (at
// least) the scheme's second order over three resolutions.
// Tight CVODE tolerances keep the time error well below the spatial one.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/comparison/depthavg_linear_run.hpp"
#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"
#include "tests/support/verification_table.hpp"

namespace granbench {
namespace {

TEST(DepthAvgConvergence, GrowthAndSpeedErrorsFallAtSecondOrder) {
  const Material m;
  const MuCurve curve(CurveKind::Regularised, m, 4e-3);
  const SteadyState s = steady_state(curve, degrees_to_radians(28.5), 4e-3);
  depthavg::LinearRunParams p;
  p.tolerance = 1e-7;
  p.t_end = 0.5;
  const std::size_t nx[3] = {32, 64, 128};
  double eg[3], ec[3];
  for (int i = 0; i < 3; ++i) {
    p.nx = nx[i];
    const auto r = depthavg::linear_run(s, curve, 1.0, 0.08, p);
    ASSERT_TRUE(r.ok) << r.message;
    eg[i] = r.growth_relative_error();
    ec[i] = r.speed_relative_error();
  }
  testing::VerificationTable table(
      "depthavg_linear_order", "Depth-averaged model: linear growth and speed against (7.11)",
      "Seeded mode (7.10) at Lx = 8 cm (28.5 deg, h0 = 4 mm, regularised curve), CVODE rtol 1e-7, "
      "to 0.5 s; relative errors of the measured growth rate and phase speed against (7.11).",
      {"nx", "growth error", "order", "speed error", "order"});
  table.bound("observed order of both errors > 1.8 between successive grids");
  for (int i = 0; i < 3; ++i) {
    const double order_g = i > 0 ? std::log2(eg[i - 1] / eg[i]) : NAN;
    const double order_c = i > 0 ? std::log2(ec[i - 1] / ec[i]) : NAN;
    table.row({std::to_string(nx[i]), testing::sci(eg[i]),
               i > 0 ? testing::fixed(order_g) : testing::dash(), testing::sci(ec[i]),
               i > 0 ? testing::fixed(order_c) : testing::dash()});
    if (i > 0) {
      EXPECT_GT(order_g, 1.8);
      EXPECT_GT(order_c, 1.8);
    }
  }
  table.write();
}

}  // namespace
}  // namespace granbench

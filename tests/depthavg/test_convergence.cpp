// Observed order of convergence of the depth-averaged scheme (issue 3, item 6; label
// `convergence`): the errors of the measured growth rate and phase speed of the seeded mode
// (7.10) against (7.11) fall at (at least) the scheme's second order over three resolutions.
// Tight CVODE tolerances keep the time error well below the spatial one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "depthavg/linear_run.hpp"
#include "mu_curves.hpp"
#include "steady_state.hpp"

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
    std::printf("nx %4zu  growth error %.3e  speed error %.3e\n", nx[i], eg[i], ec[i]);
  }
  for (int i = 0; i < 2; ++i) {
    const double order_g = std::log2(eg[i] / eg[i + 1]);
    const double order_c = std::log2(ec[i] / ec[i + 1]);
    std::printf("observed order %zu->%zu: growth %.2f, speed %.2f\n", nx[i], nx[i + 1], order_g,
                order_c);
    EXPECT_GT(order_g, 1.8);
    EXPECT_GT(order_c, 1.8);
  }
}

}  // namespace
}  // namespace granbench

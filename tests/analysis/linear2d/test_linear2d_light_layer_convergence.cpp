// Spectral convergence of the light-layer eigenvalue (analysis/linear2d/light_layer.hpp) in both
// resolutions: N in the grains (square-root map) with the fluid resolved, and M in the fluid
// (plain Chebyshev in z) with the grains resolved.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "analysis/linear2d/light_layer.hpp"
#include "analysis/linear2d/linear_stability_2d.hpp"
#include "tests/support/verification_table.hpp"

using namespace granbench;
using namespace granbench::linear2d;
namespace vt = granbench::testing;

namespace {
struct Case {
  LinearBaseState b;
  LightLayerScaled l;
  double k_hat;
  std::complex<double> ref;  // at N = M = 48
};
Case section7(double Lx) {
  const MuCurve c(CurveKind::Regularised, Material{}, 4e-3);
  const SteadyState s = steady_state(c, degrees_to_radians(28.5), 4e-3);
  Case k{mu_i_base_state(s, c),
         scale(LightLayer{1.5, 1e-3, 2.0}, s),
         2.0 * std::numbers::pi * s.h0 / Lx,
         {}};
  k.ref = continue_from_stress_free(k.b, k.l, k.k_hat, 48, 48,
                                    surface_mode_eigenvalue(k.b, k.k_hat, 32));
  return k;
}

// Local algebraic orders log(e_i/e_{i+1})/log(n_{i+1}/n_i) keep rising: faster than any power.
void expect_spectral(const std::vector<int>& n, const std::vector<double>& err,
                     vt::VerificationTable& table) {
  table.bound("each local order exceeds the previous one; the last > 10");
  double previous_order = 0.0;
  for (std::size_t i = 0; i < err.size(); ++i) {
    if (i == 0) {
      table.row({std::to_string(n[i]), vt::sci(err[i]), vt::dash()});
      continue;
    }
    const double order = std::log(err[i - 1] / err[i]) / std::log(double(n[i]) / n[i - 1]);
    table.row({std::to_string(n[i]), vt::sci(err[i]), vt::fixed(order)});
    EXPECT_GT(order, previous_order) << i;
    previous_order = order;
  }
  EXPECT_GT(previous_order, 10.0);
}
}  // namespace

TEST(Linear2DLightLayerConvergence, GranularResolutionConvergesSpectrally) {
  const Case c = section7(0.08);
  const std::vector<int> Ns{8, 12, 16, 20, 24};
  std::vector<double> err;
  for (int N : Ns)
    err.push_back(
        std::abs(nearest_light_layer_eigenvalue(c.b, c.l, c.k_hat, N, 48, c.ref) - c.ref) /
        std::abs(c.ref));
  vt::VerificationTable table(
      "linear2d_light_layer_grains", "2D linear stability under the light fluid: grain intervals",
      "Surface-mode eigenvalue at Lx = 8 cm under the light fluid (rho 1.5 kg/m3, eta 1e-3 Pa s, "
      "Lz = 2 h0), N Chebyshev intervals in the grains with M = 48 in the fluid, relative error "
      "against N = M = 48.",
      {"N", "relative error", "local order"});
  table.bound("the error at N = 24 < 1e-7");
  expect_spectral(Ns, err, table);
  EXPECT_LT(err.back(), 1e-7);
  table.write();
}

TEST(Linear2DLightLayerConvergence, FluidResolutionConvergesSpectrally) {
  // The fluid is smooth (nu ~ 3 in flow units): at Lx = 8 cm M = 8 is already at round-off, so
  // the shorter 2 cm wave is used.
  const Case c = section7(0.02);
  const std::vector<int> Ms{2, 3, 4, 5, 6, 8};
  std::vector<double> err;
  for (int M : Ms)
    err.push_back(
        std::abs(nearest_light_layer_eigenvalue(c.b, c.l, c.k_hat, 48, M, c.ref) - c.ref) /
        std::abs(c.ref));
  vt::VerificationTable table(
      "linear2d_light_layer_fluid", "2D linear stability under the light fluid: fluid intervals",
      "The same at Lx = 2 cm (at 8 cm M = 8 is already at round-off): M intervals in the fluid "
      "with N = 48 in the grains, relative error against N = M = 48.",
      {"M", "relative error", "local order"});
  table.bound("the error at M = 8 < 1e-10");
  expect_spectral(Ms, err, table);
  EXPECT_LT(err.back(), 1e-10);
  table.write();
}

// Spectral convergence of the light-layer eigenvalue (linear2d_light_layer.hpp) in both
// resolutions: N in the grains (square-root map) with the fluid resolved, and M in the fluid
// (plain Chebyshev in z) with the grains resolved.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "linear2d_light_layer.hpp"
#include "linear_stability_2d.hpp"

using namespace granbench;
using namespace granbench::linear2d;

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
void expect_spectral(const std::vector<int>& n, const std::vector<double>& err) {
  double previous_order = 0.0;
  for (std::size_t i = 1; i < err.size(); ++i) {
    const double order = std::log(err[i - 1] / err[i]) / std::log(double(n[i]) / n[i - 1]);
    std::printf("  observed local order %zu: %.2f\n", i, order);
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
  for (int N : Ns) {
    const auto l = nearest_light_layer_eigenvalue(c.b, c.l, c.k_hat, N, 48, c.ref);
    err.push_back(std::abs(l - c.ref) / std::abs(c.ref));
    std::printf("grains N = %2d (fluid M = 48)  relative error %.3e\n", N, err.back());
  }
  expect_spectral(Ns, err);  // observed 4.9e-4, 8.0e-5, 1.1e-5, 7.9e-7, 3.6e-8
  EXPECT_LT(err.back(), 1e-7);
}

TEST(Linear2DLightLayerConvergence, FluidResolutionConvergesSpectrally) {
  // The fluid is smooth (nu ~ 3 in flow units): at Lx = 8 cm M = 8 is already at round-off, so
  // the shorter 2 cm wave is used.
  const Case c = section7(0.02);
  const std::vector<int> Ms{2, 3, 4, 5, 6, 8};
  std::vector<double> err;
  for (int M : Ms) {
    const auto l = nearest_light_layer_eigenvalue(c.b, c.l, c.k_hat, 48, M, c.ref);
    err.push_back(std::abs(l - c.ref) / std::abs(c.ref));
    std::printf("fluid M = %d (grains N = 48)  relative error %.3e\n", M, err.back());
  }
  expect_spectral(Ms, err);  // observed 1.5e-4, 8.3e-6, 9.0e-7, 5.8e-8, 4.6e-9, 1.8e-11
  EXPECT_LT(err.back(), 1e-10);
}

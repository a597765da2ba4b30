// The 2D linear stability under the solver's light fluid (analysis/linear2d/light_layer.hpp): the
// base flow of the fluid and the loaded granular state against their closed forms, the limit of a
// vanishing layer (the stress-free problem), and the long-wave kinematic speed of the loaded
// layer, an exact limit of the coupled problem.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "analysis/linear2d/light_layer.hpp"
#include "analysis/linear2d/linear_stability_2d.hpp"

using namespace granbench;
using namespace granbench::linear2d;

namespace {
const MuCurve& curve() {
  static const MuCurve c(CurveKind::Regularised, Material{}, 4e-3);
  return c;
}
SteadyState section7() {
  return steady_state(curve(), degrees_to_radians(28.5), 4e-3);
}
constexpr double k_hat_8cm = 2.0 * std::numbers::pi * 4e-3 / 0.08;
}  // namespace

TEST(Linear2DLightLayer, FluidBaseFlowIsTheAnalyticProfile) {
  // u_l = u_s + (rho_l g sin(zeta)/eta_l) ((Lz - h0)(z - h0) - (z - h0)^2/2): eta_l u'' =
  // -rho_l g sin(zeta), u(h0) = u_s, u'(Lz) = 0, written in SI here and compared with the scaled
  // profile of the library.
  const SteadyState s = section7();
  const LightLayer layer{1.5, 1e-3, 2.03};
  const LightLayerScaled l = scale(layer, s);
  const LinearBaseState g = with_overburden(mu_i_base_state(s, curve()), l);
  const LightBaseFlow f = light_base_flow(g, l);
  const double h0 = s.h0, Lz = layer.Lz_over_h0 * h0, G = s.material.g;
  const double u_s = g.U_surface() * s.u_mean;
  for (double z : {h0, 1.3 * h0, 1.7 * h0, Lz}) {
    const double y = z - h0;
    const double u =
        u_s + layer.rho_l * G * std::sin(s.zeta) / layer.eta_l * ((Lz - h0) * y - 0.5 * y * y);
    EXPECT_NEAR(f.U(z / h0) * s.u_mean, u, 1e-13 * u) << z;
  }
  EXPECT_DOUBLE_EQ(f.dU(layer.Lz_over_h0), 0.0);  // du/dz = 0 at the top
  // eps U'' = -r mu (the second difference of a quadratic is exact).
  const double d = 0.1;
  const double U2 = (f.U(1.5 + d) - 2.0 * f.U(1.5) + f.U(1.5 - d)) / (d * d);
  EXPECT_NEAR(l.eps * U2, -l.r * std::tan(s.zeta), 1e-9 * l.r);
  // Its shear stress on the grains is the column's weight along the slope, whatever eta_l:
  // eta_l u'(h0) = rho_l g sin(zeta) (Lz - h0).
  const double stress = s.material.rho_star * s.material.phi * G * std::cos(s.zeta) * h0;
  EXPECT_NEAR(l.eps * f.dU(1.0) * stress, layer.rho_l * G * std::sin(s.zeta) * (Lz - h0), 1e-12);
}

TEST(Linear2DLightLayer, LoadedGrainsKeepTheBagnoldRateOfTheirPressure) {
  // Under the column p = rho_g g cos (h0 - z) + rho_l g cos (Lz - h0) and tau = tan(zeta) p, so
  // I = I_zeta and du/dz = I_zeta sqrt(p/rho_*)/d (2.8) everywhere in the grains.
  const SteadyState s = section7();
  const LightLayer layer{15.0, 1e-2, 2.0};
  const LinearBaseState g = with_overburden(mu_i_base_state(s, curve()), scale(layer, s));
  const Material& m = s.material;
  const double h0 = s.h0, Lz = 2.0 * h0, cz = m.g * std::cos(s.zeta);
  for (double z : {0.0, 0.5 * h0, 0.99 * h0, h0}) {
    const double p = m.rho_star * m.phi * cz * (h0 - z) + layer.rho_l * cz * (Lz - h0);
    const double dudz = s.I_zeta * std::sqrt(p / m.rho_star) / m.d;
    EXPECT_NEAR(g.dU0(z / h0) * s.u_mean / h0, dudz, 1e-12 * dudz) << z;
  }
  EXPECT_DOUBLE_EQ(g.U0(0.0), 0.0);  // no slip
}

TEST(Linear2DLightLayer, VanishingLayerGivesTheStressFreeSurface) {
  // rho_l and eta_l -> 0 together (nu fixed): lambda -> the stress-free eigenvalue, linearly in
  // rho_l (observed relative difference 1.387e-4 t for t times (1.5 kg/m^3, 1e-3 Pa s)).
  const SteadyState s = section7();
  const LinearBaseState b = mu_i_base_state(s, curve());
  const auto free = surface_mode_eigenvalue(b, k_hat_8cm, 24);
  const LightLayerScaled l = scale(LightLayer{1.5, 1e-3, 2.0}, s);
  double previous = 0.0;
  for (double t : {1.0, 0.1, 0.01, 1e-3}) {
    const auto lambda = continue_from_stress_free(b, l.scaled_by(t), k_hat_8cm, 24, 12, free);
    const double rel = std::abs(lambda - free) / std::abs(free);
    std::printf("rho_l = %.4g kg/m^3: relative difference %.3e\n", 1.5 * t, rel);
    if (previous > 0.0) {
      EXPECT_NEAR(previous / rel, 10.0, 0.1);  // linear in rho_l
    }
    previous = rel;
  }
  const auto tiny = continue_from_stress_free(b, l.scaled_by(1e-6), k_hat_8cm, 24, 12, free);
  EXPECT_LT(std::abs(tiny - free) / std::abs(free), 1e-8);
  EXPECT_GT(l.nu(), 1.0);  // the solver's fluid is viscous on the scale of the flow
}

TEST(Linear2DLightLayer, LongWavesTravelAtTheKinematicSpeedOfTheLoadedLayer) {
  // As k -> 0 the interface moves with dQ/dh of the local uniform state, whose overburden is
  // r (L - h): with a = h + r (L - h) and Q = (5/3)(h a^{3/2} - (2/5)(a^{5/2} - (r(L-h))^{5/2})),
  //   dQ/dh(1) = (5/3)(r a^{3/2} + (3/2)(1 - r) a^{1/2} - r delta^{3/2}),  delta = r ell.
  // (5/2 at r = 0.) A dense fluid makes the shift visible: r = 0.1 and 0.01.
  const SteadyState s = section7();
  const LinearBaseState b = mu_i_base_state(s, curve());
  for (double rho : {150.0, 15.0}) {
    const LightLayerScaled l = scale(LightLayer{rho, rho * 1e-3 / 1.5, 2.0}, s);
    const double r = l.r, delta = l.overburden(), a = 1.0 + delta;
    const double c = (5.0 / 3.0) * (r * std::pow(a, 1.5) + 1.5 * (1.0 - r) * std::sqrt(a) -
                                    r * std::pow(delta, 1.5));
    double previous = 0.0;
    for (double k : {1e-4, 1e-5, 1e-6}) {
      const auto free = surface_mode_eigenvalue(b, k, 24);
      const auto lambda = continue_from_stress_free(b, l, k, 24, 12, free);
      const double deficit = c - (-lambda.imag() / k);
      std::printf("r = %.2g, k_hat = %.0e: speed %.10f, dQ/dh %.10f\n", r, k, -lambda.imag() / k,
                  c);
      EXPECT_GT(deficit, 0.0);
      if (previous > 0.0) {
        EXPECT_NEAR(previous / deficit, 100.0, 2.0) << k;  // ~ k^2
      }
      previous = deficit;
    }
    EXPECT_LT(previous, 1e-6);
    EXPECT_GT(c - 2.5, 1e3 * previous);  // the loaded speed, not the stress-free 5/2
  }
}

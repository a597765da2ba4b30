// The granular viscosity (2.11) with its regularisation and the interface mixing rules
// (properties.cpp): exact values for simple shear, the cap, the floor, the clipped pressure,
// and both mixing rules at f = 0, 1/2, 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "twod/properties.hpp"

using namespace granbench;
using namespace granbench::twod;

TEST(Properties, GranularViscosityIsMuPOverTwoD) {
  Rheology r;
  const ViscosityModel m(r);
  const double p = 30.0, D = 20.0;
  const double I = 2.0 * r.material.d * D / std::sqrt(p / r.material.rho_star);  // (2.8)
  EXPECT_NEAR(m.inertial_number(p, D), I, 1e-14 * I);
  EXPECT_NEAR(m.granular(p, D), m.curve().mu(I) * p / (2.0 * D), 1e-14);  // (2.11)
}

TEST(Properties, RegularisationCapFloorAndClippedPressure) {
  Rheology r;
  r.eta_max = 2.0;
  r.eta_min = 1e-3;
  const ViscosityModel m(r);
  EXPECT_DOUBLE_EQ(m.granular(50.0, 0.0), 2.0);     // |D| floored -> capped
  EXPECT_DOUBLE_EQ(m.granular(-5.0, 10.0), 1e-3);   // p clipped at 0 -> floor
  EXPECT_DOUBLE_EQ(m.granular(1e-9, 100.0), 1e-3);  // tiny stress -> floor
  EXPECT_TRUE(std::isinf(m.inertial_number(0.0, 1.0)));
}

TEST(Properties, MixingRules) {
  Rheology r;
  r.eta_light = 1e-3;
  r.mixing = ViscosityMixing::Arithmetic;
  const ViscosityModel a(r);
  EXPECT_DOUBLE_EQ(a.mix(1.0, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(a.mix(0.0, 0.5), 1e-3);
  EXPECT_DOUBLE_EQ(a.mix(0.5, 0.5), 0.2505);
  r.mixing = ViscosityMixing::Harmonic;
  const ViscosityModel h(r);
  EXPECT_DOUBLE_EQ(h.mix(1.0, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(h.mix(0.0, 0.5), 1e-3);
  EXPECT_NEAR(h.mix(0.5, 0.5), 1.0 / (0.5 / 0.5 + 0.5 / 1e-3), 1e-15);
}

// mixture_with_tangent_many, the vectorised path of update_viscosity, against the scalar
// composition it replaces (granular_with_tangent, then mix and mix_tangent with the tangent
// weighted by the share of |D|^2), bitwise: every branch (light fluid, full, mixed; p <= 0, |D|
// at its floor, eta capped and floored, the low-I branch) under both mixing rules and the
// Newtonian override, over lengths that leave the vector loop remainders.
TEST(Properties, BatchMixtureViscosityIsBitwiseTheScalarOne) {
  std::vector<double> f, p, D, weight;
  for (double fr : {0.0, 1e-9, 0.3, 1.0})
    for (double pr : {-2.0, 0.0, 1e-9, 0.5, 30.0, 400.0})
      for (double Dv : {0.0, 1e-7, 0.02, 5.0, 40.0, 3000.0})
        for (double w : {0.0, 0.5, 1.0}) {
          f.push_back(fr);
          p.push_back(pr);
          D.push_back(Dv);
          weight.push_back(w);
        }
  for (ViscosityMixing mixing : {ViscosityMixing::Arithmetic, ViscosityMixing::Harmonic})
    for (double newtonian : {0.0, 0.7}) {
      Rheology r;
      r.mixing = mixing;
      r.newtonian_eta = newtonian;
      r.eta_light = 1e-3;
      const ViscosityModel m(r);
      for (std::size_t n : {f.size(), f.size() - 5, std::size_t(3)}) {
        std::vector<double> eta(n), eta_t(n);
        m.mixture_with_tangent_many(std::span(f.data(), n), std::span(p.data(), n),
                                    std::span(D.data(), n), std::span(weight.data(), n), eta,
                                    eta_t);
        for (std::size_t j = 0; j < n; ++j) {
          double expected = r.eta_light, expected_t = r.eta_light;
          if (f[j] > 0.0) {
            const auto [eta_g, ratio] = m.granular_with_tangent(p[j], D[j]);
            const double eta_gt = eta_g * (1.0 - (1.0 - ratio) * weight[j]);
            expected = m.mix(f[j], eta_g);
            expected_t = m.mix_tangent(f[j], eta_g, eta_gt);
          }
          EXPECT_EQ(eta[j], expected) << "f " << f[j] << " p " << p[j] << " D " << D[j];
          EXPECT_EQ(eta_t[j], expected_t) << "f " << f[j] << " p " << p[j] << " D " << D[j];
        }
      }
      // a stretch of light fluid only (the rows above the surface skip mu(I) altogether)
      const std::size_t n = 300;
      const std::vector<double> none(n, 0.0);
      std::vector<double> eta(n), eta_t(n);
      m.mixture_with_tangent_many(none, std::span(p.data(), n), std::span(D.data(), n),
                                  std::span(weight.data(), n), eta, eta_t);
      for (std::size_t j = 0; j < n; ++j) {
        EXPECT_EQ(eta[j], r.eta_light);
        EXPECT_EQ(eta_t[j], r.eta_light);
      }
    }
}

// Rheology::surface_row_shear_spacing: with a Newtonian granular phase the corner below a partly
// filled surface row (fraction f) carries 2/(1 + f) times the viscosity, so that the stencil's
// (u_k - u_{k-1})/dz gives the stress of the shear over the distance (1 + f) dz / 2 to the
// grains' centroid; corners below full rows keep theirs, and the scale tends to 1 as f -> 1.
TEST(Properties, SurfaceRowShearSpacingScalesTheCornerBelowAPartlyFilledRow) {
  const Grid g(4, 8, 0.004, 0.008);  // dz = 1 mm
  for (double fill : {0.25, 0.5, 0.75, 0.999}) {
    Fields s(g);
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) {
        s.f[g.at(i, k)] = k < 3 ? 1.0 : (k == 3 ? fill : 0.0);
        s.u[g.at(i, k)] = 0.1 * g.zc(k);
        s.p[g.at(i, k)] = std::max(3.0 + fill - (k + 0.5), 0.0) * 30.0;
      }
    Rheology r;
    r.newtonian_eta = 0.01;
    r.surface_row_shear_spacing = false;
    const ViscosityModel plain(r);
    r.surface_row_shear_spacing = true;
    const ViscosityModel spaced(r);
    Properties a(g), b(g);
    update_viscosity(g, s, s.p, plain, a);
    update_viscosity(g, s, s.p, spaced, b);
    for (int i = 0; i < g.nx; ++i) {
      EXPECT_NEAR(b.eta_n[g.at(i, 3)], 2.0 / (1.0 + fill) * a.eta_n[g.at(i, 3)], 1e-14) << fill;
      EXPECT_NEAR(b.eta_n_tangent[g.at(i, 3)], 2.0 / (1.0 + fill) * a.eta_n_tangent[g.at(i, 3)],
                  1e-14);
      for (int k : {1, 2, 4}) EXPECT_EQ(b.eta_n[g.at(i, k)], a.eta_n[g.at(i, k)]) << k;
    }
  }
}

TEST(Properties, TheSurfaceRowsStrainRateIsItsGrainsShear) {
  // The surface row's |D| takes the shear of its two lower (granular) corners over the shear
  // spacing (1 + f) dz / 2, not the mean of four corners whose upper two lie in the light fluid:
  // here the light fluid above is sheared ten times as fast as the grains, and I in the surface
  // row must not see it. Rows below take the four-corner mean as before.
  const Grid g(4, 8, 0.004, 0.008);  // dz = 1 mm
  const double grains_shear = 2.0, light_shear = 20.0;
  for (double fill : {0.25, 0.5, 0.75}) {
    Fields s(g);
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) {
        s.f[g.at(i, k)] = k < 3 ? 1.0 : (k == 3 ? fill : 0.0);
        s.u[g.at(i, k)] = k <= 3 ? grains_shear * g.zc(k)
                                 : grains_shear * g.zc(3) + light_shear * (g.zc(k) - g.zc(3));
        s.p[g.at(i, k)] = std::max(3.0 + fill - (k + 0.5), 0.0) * 30.0 + 20.0;  // I finite
      }
    Rheology r;
    r.surface_row_shear_spacing = true;
    const ViscosityModel model(r);
    Properties props(g);
    update_viscosity(g, s, s.p, model, props);
    // the stencil's gamma at the surface row's lower corners is grains_shear (u over dz)
    const double D_surface = 0.5 * grains_shear * 2.0 / (1.0 + fill);
    const double D_below = 0.5 * grains_shear;  // row 2: four granular corners
    for (int i = 0; i < g.nx; ++i) {
      EXPECT_NEAR(props.I_c[g.at(i, 3)], model.inertial_number(s.p[g.at(i, 3)], D_surface),
                  1e-12 * props.I_c[g.at(i, 3)])
          << fill;
      EXPECT_NEAR(props.I_c[g.at(i, 2)], model.inertial_number(s.p[g.at(i, 2)], D_below),
                  1e-12 * props.I_c[g.at(i, 2)]);
    }
  }
}

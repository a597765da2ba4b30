// The granular viscosity (2.11) with its regularisation and the interface mixing rules
// (properties.cpp): exact values for simple shear, the cap, the floor, the clipped pressure,
// and both mixing rules at f = 0, 1/2, 1.
#include <gtest/gtest.h>

#include <cmath>

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

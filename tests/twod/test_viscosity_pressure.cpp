// The pressure the viscosity of the new level is evaluated at (twod/viscosity_pressure.cpp).
//
// eta = mu(I) p / (2|D|) needs p^{n+1}, which the projection gives only after eta is used. The
// hydrostatic part follows the surface the VOF has already moved; the dynamic rest
// d = p - p_hs(h) is extrapolated along its slope over the last two steps. Lagging it one step
// was the last first-order error of the section 7 growth rate in time (1.0724, 1.0752, 1.0765
// at cfl 0.4, 0.2, 0.1; with the extrapolation and the mid-step interface velocity 1.0762,
// 1.0773, 1.0776; docs/twod-validation.md §2). A slope over one step was tried first and
// amplified a pressure that alternates from step to step until the run blew up: the slope over
// two steps cancels such a pattern exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/steady_state.hpp"
#include "twod/viscosity_pressure.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {

struct TwoLayerColumn {
  Grid g{4, 8, 0.01, 0.008};
  SolverParams params;
  TwoLayerColumn() { params.zeta = degrees_to_radians(28.5); }
  // The two layers' hydrostatic pressure under a surface at height h (p = 0 at the lid).
  double hydrostatic(double h, double z) const {
    const double g_cos = params.rheology.material.g * std::cos(params.zeta);
    return params.rheology.material.bulk_density() * g_cos * std::max(h - z, 0.0) +
           params.rheology.rho_light * g_cos * (g.Lz - std::max(h, z));
  }
  // What mu(I) sees of a mixture pressure p: p less the light column's weight above each cell,
  // rho_l g cos(zeta) (Lz - z), with Rheology::effective_pressure (the default).
  std::vector<double> for_mu(std::vector<double> p) const {
    if (!params.rheology.effective_pressure) return p;
    const double g_cos = params.rheology.material.g * std::cos(params.zeta);
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i < g.nx; ++i)
        p[g.at(i, k)] -= params.rheology.rho_light * g_cos * (g.Lz - g.zc(k));
    return p;
  }
  // A pressure whose dynamic part is d(i, k, t) over the surface heights h.
  template <class Dynamic>
  std::vector<double> pressure(const std::vector<double>& h, double t, Dynamic d) const {
    std::vector<double> p(g.cells());
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) p[g.at(i, k)] = hydrostatic(h[i], g.zc(k)) + d(i, k, t);
    return p;
  }
};

}  // namespace

TEST(ViscosityPressure, ADynamicPressureLinearInTimeIsExtrapolatedExactly) {
  const TwoLayerColumn s;
  auto d = [](int i, int k, double t) { return 3.0 + i - 0.5 * k + (40.0 + 7.0 * k) * t; };
  const std::vector<double> h(std::size_t(s.g.nx), 0.0045);
  DynamicPressureHistory history;
  std::vector<double> p_eta;
  // uneven steps, a shortened one among them: the slope uses the times actually reached
  const double steps[] = {1e-4, 1.3e-4, 0.4e-4, 1.1e-4};
  double t = 0.2;
  for (int n = 0; n < 4; ++n) {
    const double dt = steps[n];
    viscosity_pressure(s.g, s.params, s.pressure(h, t, d), h, h, t, dt, history, p_eta);
    if (n >= 2) {  // two earlier levels known
      const std::vector<double> exact = s.for_mu(s.pressure(h, t + dt, d));
      for (std::size_t c = 0; c < exact.size(); ++c)
        EXPECT_NEAR(p_eta[c], exact[c], 1e-9 * std::abs(exact[c])) << "step " << n << " cell " << c;
    }
    t += dt;
  }
}

TEST(ViscosityPressure, APressureAlternatingFromStepToStepIsNotAmplified) {
  const TwoLayerColumn s;
  const double epsilon = 5.0;  // Pa, flipping sign every step
  const std::vector<double> h(std::size_t(s.g.nx), 0.0045);
  DynamicPressureHistory history;
  std::vector<double> p_eta;
  const double dt = 1e-4;
  for (int n = 0; n < 6; ++n) {
    const double t = 0.1 + n * dt, sign = n % 2 == 0 ? 1.0 : -1.0;
    const std::vector<double> p =
        s.pressure(h, t, [&](int, int, double) { return 100.0 + sign * epsilon; });
    viscosity_pressure(s.g, s.params, p, h, h, t, dt, history, p_eta);
    // the slope over two steps sees no change: eta takes p^n as it is, never 3 epsilon off as
    // the slope over one step would make it
    const std::vector<double> seen = s.for_mu(p);
    for (std::size_t c = 0; c < p.size(); ++c) EXPECT_NEAR(p_eta[c], seen[c], 1e-9 * p[c]);
  }
}

TEST(ViscosityPressure, TheHydrostaticPartFollowsTheMovedSurface) {
  const TwoLayerColumn s;
  std::vector<double> h_before(std::size_t(s.g.nx)), h_after(std::size_t(s.g.nx));
  for (int i = 0; i < s.g.nx; ++i) {
    h_before[i] = 0.0040 + 0.0002 * i;
    h_after[i] = h_before[i] + (i % 2 == 0 ? 0.0003 : -0.0004);  // across cell faces (dz 1 mm)
  }
  auto d = [](int i, int, double) { return 12.0 * i; };
  DynamicPressureHistory history;
  std::vector<double> p_eta, p_lagged;
  const std::vector<double> p = s.pressure(h_before, 0.0, d);
  viscosity_pressure(s.g, s.params, p, h_before, h_after, 0.0, 1e-4, history, p_eta);
  viscosity_pressure(s.g, s.params, p, h_before, h_after, p_lagged);
  const std::vector<double> exact = s.for_mu(s.pressure(h_after, 0.0, d));
  for (std::size_t c = 0; c < exact.size(); ++c) {
    EXPECT_NEAR(p_eta[c], exact[c], 1e-9 * (1.0 + std::abs(exact[c])));
    EXPECT_NEAR(p_lagged[c], exact[c], 1e-9 * (1.0 + std::abs(exact[c])));
  }
}

// Rheology::effective_pressure: the light fluid's hydrostatic pressure, which the pores carry,
// is not a load on the grains' contacts. Under a flat surface at rest the pressure for mu(I) is
// then the grains' buoyant weight alone, (rho_g - rho_l) g cos(zeta) (h - z), as in the Bagnold
// layer with the surface stress free, whatever the light fluid's density; without the option it
// is the mixture's pressure, with the light column's weight on top.
TEST(ViscosityPressure, TheEffectivePressureLeavesOutTheLightColumn) {
  for (double rho_light : {0.015, 1.5}) {
    TwoLayerColumn s;
    s.params.rheology.rho_light = rho_light;
    const double h = 0.0045, g_cos = s.params.rheology.material.g * std::cos(s.params.zeta);
    const std::vector<double> heights(std::size_t(s.g.nx), h);
    const std::vector<double> p = s.pressure(heights, 0.0, [](int, int, double) { return 0.0; });
    std::vector<double> mixture, effective, lagged;
    s.params.rheology.effective_pressure = false;
    effective_pressure(s.g, s.params, p, mixture);
    s.params.rheology.effective_pressure = true;
    effective_pressure(s.g, s.params, p, effective);
    viscosity_pressure(s.g, s.params, p, heights, heights, lagged);
    for (int k = 0; k < s.g.nz; ++k)
      for (int i = 0; i < s.g.nx; ++i) {
        const std::size_t c = s.g.at(i, k);
        const double z = s.g.zc(k);
        EXPECT_DOUBLE_EQ(mixture[c], p[c]);
        EXPECT_NEAR(lagged[c], effective[c], 1e-12 * (1.0 + std::abs(p[c])));
        if (z < h) {  // the grains: their buoyant weight only
          const double buoyant =
              (s.params.rheology.material.bulk_density() - rho_light) * g_cos * (h - z);
          EXPECT_NEAR(effective[c], buoyant, 1e-12 * p[c]) << "rho_l " << rho_light;
        } else {  // the light fluid carries no contact pressure
          EXPECT_NEAR(effective[c], 0.0, 1e-12 * (1.0 + p[c]));
        }
      }
  }
}

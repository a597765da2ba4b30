// How much of the linearised mu(I) stress stays explicit (twod/explicit_stress_limit.cpp). Inside
// the grains the matrix keeps the tangent; a stress point beside a face of light fluid keeps its
// whole secant implicit, so that the explicit stress never moves a face by more than its own mass
// allows: (eta - eta_m) dt / (rho_min h^2) <= 1 at every cell and corner.
#include <gtest/gtest.h>

#include <algorithm>

#include "twod/explicit_stress_limit.hpp"
#include "twod/fields.hpp"
#include "twod/grid.hpp"

using namespace granbench::twod;

namespace {
constexpr double kGrains = 1500.0, kLight = 0.015;

// Every face full of grains, eta = 1 Pa s and eta_t = 0.1 Pa s everywhere.
Properties granular(const Grid& g) {
  Properties p(g);
  std::fill(p.rho_u.begin(), p.rho_u.end(), kGrains);
  std::fill(p.rho_w.begin(), p.rho_w.end(), kGrains);
  std::fill(p.eta_c.begin(), p.eta_c.end(), 1.0);
  std::fill(p.eta_n.begin(), p.eta_n.end(), 1.0);
  std::fill(p.eta_c_tangent.begin(), p.eta_c_tangent.end(), 0.1);
  std::fill(p.eta_n_tangent.begin(), p.eta_n_tangent.end(), 0.1);
  return p;
}
}  // namespace

TEST(ExplicitStressLimit, TheGrainsKeepTheTangentAndPointsBesideALightFaceTheSecant) {
  const Grid g(6, 5, 6e-3, 5e-3);  // h = 1 mm
  Properties p = granular(g);
  // a step at which the grains carry 0.9 Pa s explicitly with room to spare: 1500 h^2/dt = 15
  const double dt = kGrains * 1e-6 / 15.0;
  // one u-face of light fluid, at x = 0 (the periodic seam) in row 2
  p.rho_u[g.at(0, 2)] = kLight;
  std::vector<double> ec, en;
  implicit_viscosities(g, p, dt, ec, en);
  // cells (5, 2) and (0, 2) share that face (through the seam); corners (0, 2) and (0, 3) have it
  // as their u-face above and below
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const bool beside = k == 2 && (i == 0 || i == 5);
      EXPECT_NEAR(ec[g.at(i, k)], beside ? 1.0 - kLight * 1e-6 / dt : 0.1, 1e-12) << i << " " << k;
    }
  for (int k = 0; k <= g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const bool beside = i == 0 && (k == 2 || k == 3);
      EXPECT_NEAR(en[g.at(i, k)], beside ? 1.0 - kLight * 1e-6 / dt : 0.1, 1e-12) << i << " " << k;
    }
}

TEST(ExplicitStressLimit, NoPointLeavesMoreExplicitStressThanItsLightestFaceCarries) {
  const Grid g(8, 6, 8e-3, 3e-3);  // dx = 1 mm, dz = 0.5 mm: h = dz
  Properties p = granular(g);
  // a pocket of light fluid under grains: the faces of cells (3..4, 2) hold light fluid only,
  // and those around it a mixture
  for (int i = 3; i <= 5; ++i) p.rho_u[g.at(i, 2)] = kLight;
  for (int i = 3; i <= 4; ++i) {
    p.rho_w[g.at(i, 2)] = 0.5 * (kGrains + kLight);
    p.rho_w[g.at(i, 3)] = 0.5 * (kGrains + kLight);
  }
  const double h2 = 0.5e-3 * 0.5e-3;
  for (const double dt : {1e-5, 1e-4, 1e-3}) {
    std::vector<double> ec, en;
    implicit_viscosities(g, p, dt, ec, en);
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) {
        const std::size_t c = g.at(i, k);
        const double rho = lightest_face_density_around_cell(g, p, i, k);
        EXPECT_LE((p.eta_c[c] - ec[c]) * dt / (rho * h2), 1.0 + 1e-12) << i << " " << k;
        EXPECT_GE(ec[c], p.eta_c_tangent[c]);
        EXPECT_LE(ec[c], p.eta_c[c]);
      }
    for (int k = 0; k <= g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) {
        const std::size_t n = g.at(i, k);
        const double rho = lightest_face_density_around_corner(g, p, i, k);
        EXPECT_LE((p.eta_n[n] - en[n]) * dt / (rho * h2), 1.0 + 1e-12) << i << " " << k;
        EXPECT_GE(en[n], p.eta_n_tangent[n]);
      }
  }
  // the corner between the pocket's two cells, at its floor: a light u-face above it
  EXPECT_DOUBLE_EQ(lightest_face_density_around_corner(g, p, 4, 2), kLight);
  // a corner on the bed has one u-face, above it
  EXPECT_DOUBLE_EQ(lightest_face_density_around_corner(g, p, 4, 0), kGrains);
}

// The consistent momentum transport (twod/momentum_advection.cpp) takes each face value from the
// side the face's mass comes from. A staggered control volume's face carries the average of two
// cells' mass fluxes C, while the average of their velocities V can point the other way: at an
// overturned front, grains sink through one half of the face while the light fluid beside them
// rises faster. Taken from V's upwind side, the momentum that leaves with the grains is the
// neighbour's, not the volume's own, and the update stops being a weighted mean of the volume's
// velocity and what flows in. That anti-diffusion grew a face's velocity by about 10 % per step
// under an overturned front of the paper's 12 cm rollwave at 48 cells per h0
// (docs/twod-validation.md §11 item 9) until the run stopped at 54 m/s.
//
// Set-up: two volumes of a 16 x 12 grid (dx, dz and dt of that run), each with one face where C
// and V disagree and every other carrier zero, the velocity uniform along the other direction so
// that no transverse term acts:
// - the u-volume at (4, 6): its bottom face carries grains down (C < 0: out) while the light
//   fluid beside rises (V > 0); its row at -1 m/s, the rows below at 1.5 m/s;
// - the u-volume at (11, 6): its right face carries grains right (C > 0: out) while the light
//   fluid at the next face runs left at 3 m/s (V < 0); its column and the three before it at
//   0.2 m/s.
// Mass that leaves takes the volume's own velocity with it, so one step changes neither volume's
// velocity; taken from V's side (the code before the 51st session) they went from -1 to -391 m/s
// and from 0.2 to 2.53 m/s.
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "twod/momentum_advection.hpp"

using namespace granbench::twod;

TEST(UpwindByMassFlux, MassThatLeavesAVolumeTakesTheVolumesOwnMomentum) {
  const int nx = 16, nz = 12;
  const Grid g(nx, nz, nx * 3.33e-4, nz * 8.42e-5);
  const double dt = 3.5e-5, rho_g = 900.0, rho_l = 0.0015;
  Fields s(g);
  MassFluxes m;
  m.x.assign(g.cells(), 0.0);
  m.z.assign(g.w_faces(), 0.0);
  std::fill(s.u.begin(), s.u.end(), 0.6);
  std::fill(s.w.begin(), s.w.end(), 0.0);
  // the first volume: columns 2-6 below row 6 at 1.5 m/s, from row 6 up at -1 m/s
  for (int k = 0; k < nz; ++k)
    for (int i = 2; i <= 6; ++i) s.u[g.at(i, k)] = k < 6 ? 1.5 : -1.0;
  s.w[g.at(3, 6)] = -0.2;  // grains sinking through the w-face under cell (3, 6)
  s.w[g.at(4, 6)] = 1.0;   // light fluid rising through the one under cell (4, 6)
  m.z[g.at(3, 6)] = rho_g * s.w[g.at(3, 6)];
  m.z[g.at(4, 6)] = rho_l * s.w[g.at(4, 6)];
  // the second volume: u-faces 8-11 at 0.2 m/s, grains at 11; u-face 12 at -3 m/s, light fluid;
  // columns uniform so that nothing varies along z
  for (int k = 0; k < nz; ++k) {
    for (int i = 8; i <= 11; ++i) s.u[g.at(i, k)] = 0.2;
    s.u[g.at(12, k)] = -3.0;
  }
  m.x[g.at(11, 6)] = rho_g * s.u[g.at(11, 6)];
  m.x[g.at(12, 6)] = rho_l * s.u[g.at(12, 6)];
  // both volumes mostly light fluid, as the faces under the front were
  std::vector<double> rho_u(g.cells(), rho_g), rho_w(g.w_faces(), rho_g);
  rho_u[g.at(4, 6)] = 0.24;
  rho_u[g.at(11, 6)] = 13.0;

  const double V_bottom = 0.5 * (s.w[g.at(3, 6)] + s.w[g.at(4, 6)]);
  const double C_bottom = 0.5 * (m.z[g.at(3, 6)] + m.z[g.at(4, 6)]);
  const double V_right = 0.5 * (s.u[g.at(11, 6)] + s.u[g.at(12, 6)]);
  const double C_right = 0.5 * (m.x[g.at(11, 6)] + m.x[g.at(12, 6)]);
  ASSERT_GT(V_bottom, 0.0);  // the set-up's point: velocity and mass flux disagree
  ASSERT_LT(C_bottom, 0.0);
  ASSERT_LT(V_right, 0.0);
  ASSERT_GT(C_right, 0.0);

  std::vector<double> adv_u, adv_w;
  AdvectionFaces faces;
  consistent_momentum_advection(g, s, m, rho_u, rho_w, dt, faces, adv_u, adv_w);
  for (const auto& [i, u_before] : {std::pair{4, -1.0}, std::pair{11, 0.2}}) {
    const double u_after = u_before - dt * adv_u[g.at(i, 6)];
    EXPECT_NEAR(u_after, u_before, 1e-12) << "the u-volume at (" << i << ", 6)";
  }
}

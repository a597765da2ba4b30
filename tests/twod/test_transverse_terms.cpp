// The consistent momentum transport's face values centred in time across the face
// (SolverParams::advection_transverse_terms, twod/momentum_advection.cpp), checked against an
// exact answer. A field q = x z carried by a uniform velocity (U, W) over one step dt is exactly
//   q(x - U dt, z - W dt) = x z - dt (U z + W x) + dt^2 U W,
// so the transport term A with q - dt A = that is A = U z + W x - dt U W. The bilinear field is
// linear along every grid line, so the limited MUSCL-Hancock slopes and the donor-cell transverse
// differences are exact for it: with the transverse terms the operator must return A to
// round-off; without them it misses the cross term, -dt U W, which is the half-step lag across
// the face that travels with a wave over the grid (docs/twod-validation.md §10).
// The field is carried as the operator's second field (the BDF2 memory's slot), with unit
// densities and mass fluxes equal to the velocity; it is checked away from the periodic seam and
// from the bed and top, where q = x z is not what the boundary conditions hold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "twod/momentum_advection.hpp"

using namespace granbench::twod;

namespace {
struct Residual {
  double u = 0.0, w = 0.0;  // largest |A - exact| at interior u- and w-faces
};

Residual transport_error(bool transverse, double U, double W, double dt, double& cross_term) {
  const Grid g(32, 24, 0.032, 0.024);
  Fields s(g);
  std::fill(s.u.begin(), s.u.end(), U);
  std::fill(s.w.begin(), s.w.end(), W);
  std::vector<double> qu(g.cells()), qw(g.w_faces());
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) qu[g.at(i, k)] = i * g.dx * g.zc(k);  // u at (i dx, zc)
  for (int k = 0; k <= g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) qw[g.at(i, k)] = g.xc(i) * k * g.dz;  // w at (xc, k dz)
  MassFluxes m;
  m.x.assign(g.cells(), U);
  m.z.assign(g.w_faces(), W);
  const std::vector<double> rho_u(g.cells(), 1.0), rho_w(g.w_faces(), 1.0);
  std::vector<double> adv_u, adv_w, carried_u, carried_w;
  AdvectionFaces faces;
  consistent_momentum_advection(g, s, m, rho_u, rho_w, dt, faces, adv_u, adv_w,
                                {&qu, &qw, &carried_u, &carried_w}, transverse);
  cross_term = dt * U * W;
  Residual r;
  for (int k = 3; k < g.nz - 3; ++k)
    for (int i = 3; i < g.nx - 3; ++i) {
      const double exact_u = U * g.zc(k) + W * i * g.dx - cross_term;
      const double exact_w = U * k * g.dz + W * g.xc(i) - cross_term;
      r.u = std::max(r.u, std::abs(carried_u[g.at(i, k)] - exact_u));
      r.w = std::max(r.w, std::abs(carried_w[g.at(i, k)] - exact_w));
    }
  return r;
}
}  // namespace

TEST(TransverseTerms, OneStepOfABilinearFieldIsTheExactTranslationInEveryDirection) {
  // Courant numbers 0.4 and 0.3 per direction, each sign of each velocity component.
  for (double su : {1.0, -1.0})
    for (double sw : {1.0, -1.0}) {
      const double U = 0.4 * su, W = 0.3 * sw, dt = 1e-3;  // dx = dz = 1 mm
      double cross = 0.0;
      const Residual with = transport_error(true, U, W, dt, cross);
      const double scale = std::abs(U) * 0.024 + std::abs(W) * 0.032;  // size of A
      EXPECT_LT(with.u, 1e-12 * scale) << "U = " << U << ", W = " << W;
      EXPECT_LT(with.w, 1e-12 * scale) << "U = " << U << ", W = " << W;
      // Without the transverse terms the cross term is missing, and only it.
      const Residual without = transport_error(false, U, W, dt, cross);
      EXPECT_NEAR(without.u, std::abs(cross), 1e-12 * scale) << "U = " << U << ", W = " << W;
      EXPECT_NEAR(without.w, std::abs(cross), 1e-12 * scale) << "U = " << U << ", W = " << W;
    }
}

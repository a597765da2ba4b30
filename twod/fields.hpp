// The state of the 2D two-phase flow on the MAC grid (grid.hpp) and the material properties
// derived from it each step (properties.cpp):
//
//   u, w   velocity components on faces [m/s]; w at k = 0 is the no-slip wall (always 0),
//          w at k = nz the open top boundary (p = 0 there)
//   p      pressure at cell centres [Pa]
//   f      granular volume fraction (VOF colour function), 1 in grains, 0 in the light fluid
//
//   rho_u, rho_w   face densities rho = f rho_* phi + (1 - f) rho_l, f averaged to the face
//   eta_c, eta_n   viscosities at cell centres and corners [Pa s] (mixing rule in properties):
//                  the secant, tau = 2 eta D
//   eta_c_tangent, eta_n_tangent   the same, tangent to tau(D) along the component each one
//                  multiplies (normal strain in cells, shear at corners); <= eta
#pragma once

#include <vector>

#include "twod/grid.hpp"

namespace granbench::twod {

struct Fields {
  std::vector<double> u, w, p, f;
  double t = 0.0;

  explicit Fields(const Grid& g = Grid())
      : u(g.cells(), 0.0), w(g.w_faces(), 0.0), p(g.cells(), 0.0), f(g.cells(), 0.0) {}
};

struct Properties {
  std::vector<double> rho_u, rho_w;  // face densities (rho_w has nz + 1 rows)
  // The face densities of the step before, against which p^n was balanced (viscous_step.cpp);
  // empty before the first step.
  std::vector<double> rho_u_before, rho_w_before;
  std::vector<double> eta_c, eta_n;  // cell-centre and corner viscosities
  std::vector<double> eta_c_tangent, eta_n_tangent;
  std::vector<double> I_c;  // inertial number (2.8) at cell centres (diagnostic)
  // The strain rates eta was evaluated from: D_xx, D_zz at cell centres and the shear rate
  // du/dz + dw/dx at corners (stored, not rebuilt per step: see PcgWorkspace for why).
  std::vector<double> D_xx_c, D_zz_c, gamma_n;
  // The surface per column, for the interface pressure (Rheology::interface_pressure): the
  // column heights, and per cell (c) or corner (n) the nearest empty row at or above it and the
  // nearest full row at or below it (properties.cpp). Kept, like the above, so that a step
  // allocates nothing.
  std::vector<double> column_height;
  // and the pressure that the cells above each column's surface take: the overburden there
  std::vector<double> surface_pressure;
  std::vector<int> empty_above_c, full_below_c, empty_above_n, full_below_n;

  explicit Properties(const Grid& g = Grid())
      : rho_u(g.cells()),
        rho_w(g.w_faces()),
        eta_c(g.cells()),
        eta_n(g.corners()),
        eta_c_tangent(g.cells()),
        eta_n_tangent(g.corners()),
        I_c(g.cells()),
        D_xx_c(g.cells()),
        D_zz_c(g.cells()),
        gamma_n(g.corners()) {}
};

}  // namespace granbench::twod

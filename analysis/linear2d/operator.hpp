// The generalised eigenproblem A v = lambda B v of the 2D linear stability of steady uniform
// chute flow, discretised by Chebyshev collocation (docs/linear-theory.md).
//
// Perturbations (u, w, p, h) ~ exp(i k x + lambda t) of the scaled base state
// (analysis/linear2d/base_state.hpp) satisfy the linearised (2.9)-(2.10)
//
//   i k u + Dw = 0,
//   F^2 ((lambda + i k U0) u + U0' w) = -i k p + i k tau_xx + D tau_xz,
//   F^2 (lambda + i k U0) w           = -D p + i k tau_xz + D tau_zz,        D = d/dz,
//
// with no slip u = w = 0 at z = 0, and at the surface z = 1 the kinematic condition
// (lambda + i k U0(1)) h = w and the stress-free conditions linearised at z = 1 + h:
//
//   tau_xz + h dtau0_xz/dz = tau_xz - mu h = 0,      -p + tau_zz + h = 0   (p0 = 1 - z).
//
// Because eta ~ sqrt(1 - z), the unknowns are functions of s = sqrt(1 - z) (map z = 1 - s^2),
// not of z. Written as a first-order system in s for u, w, the shear stress T = tau_xz and the
// normal stress N = p - tau_zz, every coefficient is regular at s = 0 (each equation is
// multiplied by dz/ds; the divided-out factor of the constitutive law is eta_s/(dz/ds) = -Gamma/5):
//
//   T - (eta_s/z_s) u_s - i k eta_s w - q (N - 2 i k eta_n u) = 0       [bed row: u = 0]
//   w_s + i k z_s u = 0                                                 [bed row: w = 0]
//   T_s - z_s (F^2 (lambda + i k U0) u + F^2 U0' w + i k N + 4 eta_n k^2 u) = 0   [surface: T = mu
//   h] N_s - z_s (i k T - F^2 (lambda + i k U0) w) = 0                              [surface: N =
//   h]
//
// With an overburden delta on the surface (LinearBaseState::overburden, the light fluid of
// analysis/linear2d/light_layer.hpp) eta ~ sqrt(1 - z + delta) and the map is z = 1 + delta - s^2,
// s in [sqrt(delta), sqrt(1 + delta)]; the surface rows above stay the stress-free ones, and the
// light layer adds the fluid's stresses to them.
// The plain map z = 1 - s is also provided, to show what the degenerate viscosity does to it.
// Unknown vector: u(s_0..s_N), w(...), N(...), T(...), h, with s_0 = 1 the bed and s_N = 0 the
// surface. B is singular (the constraint and boundary rows): only N of the 4N + 5 eigenvalues
// are finite.
#pragma once

#include <Eigen/Dense>

#include "analysis/linear2d/base_state.hpp"
#include "analysis/linear2d/chebyshev.hpp"

namespace granbench::linear2d {

enum class VerticalMap {
  SquareRoot,  // z = 1 - s^2: removes the sqrt(1 - z) degeneracy of eta (default)
  Linear,      // z = 1 - s: plain Chebyshev in z; the mu(I) eigenfunctions are not smooth in it
};

struct Pencil {
  Eigen::MatrixXcd A;
  Eigen::MatrixXcd B;
  int N = 0;
  VerticalMap map = VerticalMap::SquareRoot;
  // Offsets of the blocks in the unknown vector.
  int u() const { return 0; }
  int w() const { return N + 1; }
  int normal() const { return 2 * (N + 1); }
  int shear() const { return 3 * (N + 1); }
  int h() const { return 4 * (N + 1); }
};

// Height z in [0, 1] of the node s for the map.
double map_height(VerticalMap map, double s);
// s in [0, 1] of the height z in [0, 1] (inverse of map_height).
double map_coordinate(VerticalMap map, double z);

// A sensitivity probe of the surface mode (bench/twod_linear_check, docs/twod-validation.md):
// within the scaled depth 1 - z < depth below the surface, eta_n, eta_s and q are multiplied by
// the given factors. The default (depth 0) leaves the operator as derived.
struct SurfaceLayerScaling {
  double depth = 0.0;
  double eta_n = 1.0, eta_s = 1.0, q = 1.0;
};

// Assemble A and B for wavenumber k_hat = k h0 on the grid. Throws std::invalid_argument if the
// map cannot carry the viscosity profile (the Newtonian film needs the linear map).
Pencil assemble_pencil(const LinearBaseState& b, double k_hat, const ChebyshevGrid& grid,
                       VerticalMap map, const SurfaceLayerScaling& layer = {});

}  // namespace granbench::linear2d

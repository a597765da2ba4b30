// The 2D linear stability of the Bagnold flow under a light Newtonian fluid: the system the 2D
// solver simulates (twod/, docs/design.md §7), where the grains (density rho_g = rho_* phi) lie
// under a fluid of density rho_l and viscosity eta_l filling h0 < z < Lz, with p = 0 and du/dz = 0
// at the open top z = Lz. docs/linear-theory.md §11 derives it; the stress-free problem is
// analysis/linear2d/operator.hpp.
//
// Scales as there (length h0, speed u_bar_0, time h0/u_bar_0, stress rho_g g cos(zeta) h0), so
// the fluid enters through three numbers,
//
//   r = rho_l/rho_g,   eps = eta_l u_bar_0/(rho_g g cos(zeta) h0^2),   ell = Lz/h0 - 1,
//
// and nu = eps/r (its scaled kinematic viscosity), mu = tan(zeta).
//
// Base state. The fluid column: eps U_l'' = -r mu, U_l(1) = U0(1), U_l'(1 + ell) = 0, so
//
//   U_l = U0(1) + (mu/nu) (ell (z - 1) - (z - 1)^2/2),   P_l = r (1 + ell - z),
//
// and on the grains it puts the pressure and the shear traction r ell and mu r ell: the weight
// of the column, normal and along the slope. Their ratio is tan(zeta), so mu(I) = tan(zeta) and
// I = I_zeta still hold in the grains, exactly: the granular state is the Bagnold profile of a
// layer 1 + delta deep, cut at z = 1, with delta = r ell (LinearBaseState::overburden). This is
// kept exactly; it also keeps eta > 0 at the surface (eta ~ sqrt(1 - z + delta)).
//
// Perturbations ~ exp(i k x + lambda t) in the fluid obey the linearised Navier-Stokes equations
// in the first-order form of the granular problem (eta_n = eta_s = eps, q = 0, density r):
// with the strain rate T = Du + i k w (shear stress eps T) and N = (p - 2 eps Dw)/r,
//
//   Du + i k w - T = 0,                      Dw + i k u = 0,
//   nu DT = F^2 ((lambda + i k U_l) u + U_l' w) + i k N + 4 nu k^2 u,
//   DN = i k nu T - F^2 (lambda + i k U_l) w.
//
// Scaling T by eps and N by r keeps every row O(1) as rho_l, eta_l -> 0 at fixed nu, so the
// fluid decouples smoothly from the grains in that limit (the stress-free problem).
//
// Interface z = 1 + h, linearised at z = 1 with the base-state jumps times h (velocity,
// stress; the base sigma_xx and sigma_xz are continuous, so the slope terms cancel):
//
//   u_l = u_g + h (U0'(1) - U_l'(1)),   w_l = w_g,                     (continuity of velocity)
//   T_g - mu (1 - r) h = eps T,                                         (shear stress)
//   N_g - (1 - r) h = r N,      N_g = p_g - tau_zz,g,                   (normal stress)
//   (lambda + i k U0(1)) h = w_g(1).                                    (kinematic)
//
// Top z = 1 + ell: p = 0 (r N + 2 eps Dw = 0, i.e. N - 2 i k nu u = 0) and du/dz = 0 (T = i k w).
// The solver sets dw/dz = 0 on its predicted velocity only; after the projection w satisfies
// continuity, dw/dz = -du/dx, so p = 0 and du/dz = 0 are the two conditions it imposes.
//
// Discretisation: Chebyshev collocation in z on [1, 1 + ell] (the fluid is regular: no map), M + 1
// nodes, node 0 the top and node M the interface; the continuity-of-velocity conditions replace
// the first two equations at the interface, the top conditions the last two at the top. The
// unknowns are appended after those of the granular pencil, whose two surface stress rows get
// the fluid's stresses.
#pragma once

#include <complex>
#include <vector>

#include "analysis/linear2d/base_state.hpp"
#include "analysis/linear2d/chebyshev.hpp"
#include "analysis/linear2d/operator.hpp"
#include "common/steady_state.hpp"

namespace granbench::linear2d {

// The light fluid of the 2D solver. The member defaults are the paper's air and the default lid
// Lz = 2 h0, not the solver's light fluid: analysis does not depend on twod, so the CLI passes
// twod::Rheology's rho_light and eta_light itself.
struct LightLayer {
  double rho_l = 1.5;       // density [kg m^-3], > 0
  double eta_l = 1e-3;      // viscosity [Pa s], > 0
  double Lz_over_h0 = 2.0;  // height of the top of the domain over h0, > 1
};

// The scaled numbers of the layer (see above).
struct LightLayerScaled {
  double r = 0.0;    // rho_l / rho_g
  double eps = 0.0;  // eta_l u_bar_0 / (rho_g g cos(zeta) h0^2)
  double ell = 0.0;  // Lz/h0 - 1
  double nu() const { return eps / r; }
  double overburden() const { return r * ell; }  // delta
  // The same fluid with rho_l and eta_l multiplied by t (nu fixed): the path from the
  // stress-free surface (t -> 0) to the layer (t = 1).
  LightLayerScaled scaled_by(double t) const { return {t * r, t * eps, ell}; }
};

// Throws std::invalid_argument naming the member when a value is out of range.
LightLayerScaled scale(const LightLayer& layer, const SteadyState& s);

// The steady fluid column over the granular state g (scaled).
struct LightBaseFlow {
  double U_interface = 0.0;  // U0(1) of the grains
  double mu = 0.0;
  double nu = 0.0;
  double ell = 0.0;
  double U(double z) const;   // U_l above
  double dU(double z) const;  // U_l'
};
LightBaseFlow light_base_flow(const LinearBaseState& g, const LightLayerScaled& l);

// The granular state under the layer: `stress_free` with the overburden delta = r ell.
LinearBaseState with_overburden(LinearBaseState stress_free, const LightLayerScaled& l);

// The pencil of grains plus fluid at k_hat; `g` must carry the layer's overburden.
// Size 4(N + 1) + 1 + 4(M + 1): the granular pencil's unknowns, then u, w, T, N of the fluid.
Pencil assemble_light_layer_pencil(const LinearBaseState& g, const LightLayerScaled& l,
                                   double k_hat, const ChebyshevGrid& grains,
                                   const ChebyshevGrid& fluid);

// Offsets of the fluid blocks in the unknown vector of a pencil with N granular intervals.
struct LightLayerOffsets {
  int u, w, T, N;
};
LightLayerOffsets light_layer_offsets(int N, int M);

// Finite eigenvalues, by decreasing real part (analysis/linear2d/spectrum.hpp, two shifts).
std::vector<std::complex<double>> light_layer_spectrum(const LinearBaseState& stress_free,
                                                       const LightLayerScaled& l, double k_hat,
                                                       int N, int M);

// The eigenvalue of the layer's pencil nearest to `target` (shift and invert next to it).
std::complex<double> nearest_light_layer_eigenvalue(const LinearBaseState& stress_free,
                                                    const LightLayerScaled& l, double k_hat, int N,
                                                    int M, std::complex<double> target);

// The mode of the layer continued from the stress-free eigenvalue lambda_free at the same k_hat
// and resolution: rho_l and eta_l are raised together from 1e-8 of their values to their values
// (nu fixed), following the nearest eigenvalue in steps of a factor `step`.
std::complex<double> continue_from_stress_free(const LinearBaseState& stress_free,
                                               const LightLayerScaled& l, double k_hat, int N,
                                               int M, std::complex<double> lambda_free,
                                               double step = 10.0);

}  // namespace granbench::linear2d

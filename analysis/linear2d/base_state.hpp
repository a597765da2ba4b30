// The steady uniform flow about which the 2D linear stability problem is posed, reduced to the
// coefficients of the scaled linear operator (docs/linear-theory.md, "Linearised equations").
//
// Scales: length h0, velocity u_bar_0, time h0/u_bar_0, stress rho_* phi g cos(zeta) h0 (7.13).
// In these units the Bagnold state (5.4)-(5.5) of the mu(I)-rheology is
//
//   p0 = 1 - z,   tau0_xz = mu (1 - z),   U0 = (5/3)(1 - (1 - z)^{3/2}),   U0' = (5/2)(1 -
//   z)^{1/2},
//
// and the linearised deviatoric stress (the finite-wavelength form of (3.2)-(3.3)) is
//
//   tau_xx = -tau_zz = 2 eta_n du/dx,    tau_xz = eta_s (du/dz + dw/dx) + q p,
//   eta_n = (2 mu/5)(1 - z)^{1/2},  eta_s = (I mu'/mu) eta_n = (2 Gamma/5)(1 - z)^{1/2},
//   q = mu - Gamma/2  (3.3b),  Gamma = I_zeta mu'(I_zeta),  mu = tan(zeta),
//
// so the problem depends on F (7.1), tan(zeta) and Gamma only. A Newtonian film of kinematic
// viscosity nu (Nusselt profile, the classical falling-film problem) fits the same form with
// U0 = 3 z - (3/2) z^2, eta_n = eta_s = tan(zeta)/3 and q = 0; its Reynolds number u_bar h/nu is
// 3 F^2 / tan(zeta).
#pragma once

#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"

namespace granbench::linear2d {

enum class BaseProfile { Bagnold, Nusselt };

struct LinearBaseState {
  BaseProfile profile = BaseProfile::Bagnold;
  double F = 0.0;       // Froude number u_bar_0 / sqrt(g h0 cos zeta)  (7.1)
  double mu = 0.0;      // tan(zeta): base friction, and the surface gradient of tau0_xz is -mu
  double Gamma = 0.0;   // I_zeta mu'(I_zeta), (7.9a) generalised; 0 for the Newtonian film
  double q = 0.0;       // pressure coefficient of the shear stress (3.3b); 0 for the film
  double eta_n0 = 0.0;  // eta_n = eta_n0 (1 - z)^beta
  double eta_s0 = 0.0;  // eta_s = eta_s0 (1 - z)^beta
  double beta = 0.5;    // 1/2 (mu(I): eta ~ sqrt(p0)) or 0 (Newtonian)
  // Scaled pressure delta on the surface (Bagnold only): the weight of a fluid layer above the
  // grains (analysis/linear2d/light_layer.hpp). Its shear traction is mu delta, so mu(I) =
  // tan(zeta) still holds and the state is the Bagnold profile of a layer 1 + delta deep cut at z =
  // 1: p0 = 1 - z + delta, U0' = (5/2)(1 - z + delta)^{1/2}, eta ~ (1 - z + delta)^{1/2}. 0: the
  // stress-free surface of (5.4)-(5.5).
  double overburden = 0.0;

  double U0(double z) const;   // base velocity
  double dU0(double z) const;  // dU0/dz
  double U_surface() const { return U0(1.0); }
};

// The mu(I) Bagnold state of `s` (any shared curve: only I_zeta and mu'(I_zeta) enter).
LinearBaseState mu_i_base_state(const SteadyState& s, const MuCurve& curve);
// The Newtonian falling film on slope zeta with Froude number F (u_bar over sqrt(g h cos zeta)).
LinearBaseState newtonian_film_base_state(double F, double zeta_rad);
// Reynolds number u_bar h/nu of the Newtonian film, 3 F^2/tan(zeta).
double newtonian_film_reynolds(const LinearBaseState& b);

}  // namespace granbench::linear2d

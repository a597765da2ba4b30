// Steady uniform flow down a slope of angle zeta with depth h0 (Barker & Gray 2017, §5.2, §7):
//
//   mu(I_zeta) = tan(zeta)                                  (friction balance)
//   p(z) = rho_* phi g (h0 - z) cos(zeta)                   (5.4)
//   u(z) = (2 I_zeta/3d) sqrt(phi g cos zeta) (h0^{3/2} - (h0 - z)^{3/2})       (5.5)
//   u_mean = (2 I_zeta/5d) sqrt(phi g cos zeta) h0^{3/2}    (depth average of (5.5), §7)
//   Fr = u_mean / sqrt(g h0 cos zeta) = (2 h0/5d) I_zeta sqrt(phi)              (7.1)
//
// and the coefficients of the depth-averaged linear theory (7.5)-(7.9), generalised to any curve
// (docs/design.md §4): Gamma = I_zeta mu'(I_zeta), gamma = I0/I_zeta,
// nu = 5 d sqrt(g) sin(zeta) / (9 I_zeta sqrt(phi cos zeta)), R = u_mean sqrt(h0)/nu.
#pragma once

#include "common/material.hpp"
#include "common/mu_curves.hpp"

namespace granbench {

struct SteadyState {
  Material material;
  double zeta = 0.0;       // slope angle [rad]
  double h0 = 0.0;         // depth [m]
  double I_zeta = 0.0;     // uniform inertial number
  double u_surface = 0.0;  // u(h0) [m/s]
  double u_mean = 0.0;     // depth-averaged speed u_bar_0 [m/s]
  double Fr = 0.0;         // (7.1); also F of (7.8)
  double Gamma = 0.0;      // (7.9a) generalised
  double gamma = 0.0;      // (7.9b)
  double nu = 0.0;         // (7.5) generalised [m^{1/2} s^-1]
  double R = 0.0;          // (7.6)
  double C = 0.0;          // (3.9) at I_zeta
  bool well_posed = false;

  double pressure(double z) const;  // (5.4), clipped to 0 above the surface
  double velocity(double z) const;  // (5.5), u(h0) above the surface
  // Bagnold profile of a layer of local depth h (same I_zeta), as (7.2) needs.
  double velocity_at_depth(double z, double h) const;
  double mean_velocity_at_depth(double h) const;     // (2 I_zeta/5d) sqrt(phi g cos) h^{3/2}
  double time_scale() const { return h0 / u_mean; }  // (7.13)
};

// Throws CurveRangeError (naming the slope) when tan(zeta) lies outside the curve's range.
SteadyState steady_state(const MuCurve& curve, double zeta_rad, double h0);

// The depth-averaged inertial number I = 5 d u_bar / (2 h^{3/2} sqrt(phi g cos zeta)) (from (7.1)),
// at which the depth-averaged model evaluates the shared curve (docs/design.md §4).
double depth_averaged_inertial_number(const Material& m, double zeta_rad, double h, double u_bar);

double degrees_to_radians(double deg);

}  // namespace granbench

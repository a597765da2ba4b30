// The right-hand side dU/dt = F(U) of the depth-averaged mu(I) equations (7.3)-(7.4) on a
// periodic finite-volume grid of nx cells, U = (h_j, q_j = h_j u_j) interleaved cell by cell:
//
//   dh/dt + d(q)/dx = 0                                                              (7.3)
//   dq/dt + d(chi q^2/h + g cos(zeta) h^2/2)/dx
//         = g h cos(zeta) (tan(zeta) - mu(I)) + d/dx(nu h^{3/2} du/dx)                (7.4)
//
// with mu the shared curve at the depth-averaged inertial number I = 5 d u / (2 h^{3/2}
// sqrt(phi g cos zeta)) (docs/design.md §4), nu of (7.5) (generalised, from SteadyState) and the
// momentum shape factor chi (chi = 1 is (7.4) as printed).
//
// Semi-discretisation: cell averages; face values by piecewise-linear reconstruction of (h, q)
// (unlimited centred slopes or a limiter); the second-order central-upwind flux of Kurganov,
// Noelle & Petrova (2001),
//
//   H = (a+ F(U-) - a- F(U+)) / (a+ - a-) + a+ a- / (a+ - a-) (U+ - U-),
//
// with a+- the largest/smallest characteristic speeds chi u +- sqrt(chi (chi-1) u^2 + g h cos zeta)
// at the face (eigenvalues of the flux Jacobian of (h, q) with momentum flux chi q^2/h); the
// viscous term as a centred face flux nu h_f^{3/2} (u_{j+1} - u_j)/dx; friction and gravity as a
// cell source. Each cell's derivative depends on cells j-2 .. j+2 (stencil radius 2).
//
// Co-moving frame (optional): in x' = x - c t, with U still the lab-frame (h, h u), the equations
// are dU/dt + d(F(U) - c U)/dx' = S, so the fluxes gain -c U and the characteristic speeds shift
// by -c; friction and viscosity, which depend on the lab velocity u, are unchanged. A saturated
// rollwave moving at about c is then nearly steady, and CVODE can take far longer steps.
//
// Cost: one call is four contiguous, branch-free loops over structure-of-arrays copies of (h, q)
// with two periodic ghost cells on each side, so no index wraps inside a loop and GCC vectorises
// them; u and the friction mu(I) are evaluated once per cell (mu through MuCurve::mu_many, one
// curve dispatch per call); the work arrays are allocated once, in the constructor.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"
#include "depthavg/params.hpp"

namespace granbench::depthavg {

class Rhs {
 public:
  Rhs(const SteadyState& base, const MuCurve& curve, const SpaceParams& space);

  // dU/dt = F(U); U and dUdt have size 2 nx.
  void operator()(std::span<const double> U, std::span<double> dUdt) const;

  std::size_t nx() const { return space_.nx; }
  std::size_t size() const { return 2 * space_.nx; }
  double dx() const { return dx_; }
  double x(std::size_t j) const { return (static_cast<double>(j) + 0.5) * dx_; }
  static constexpr std::size_t stencil_radius = 2;  // in cells
  const SpaceParams& space() const { return space_; }
  const SteadyState& base() const { return base_; }
  // Depth-averaged velocity u = q/h, desingularised near dry cells.
  double velocity(double h, double q) const;
  // Basal friction plus gravity, g h cos(zeta) (tan(zeta) - mu(I) sign(u)): the source of (7.4).
  // The scalar form of what operator() evaluates for all cells at once.
  double momentum_source(double h, double q) const;

 private:
  template <Reconstruction R>
  void face_fluxes() const;

  SteadyState base_;
  MuCurve curve_;
  SpaceParams space_;
  double dx_;
  double g_cos_;  // g cos(zeta)
  double tan_zeta_;
  double h_dry_;
  double inertial_scale_;  // I = inertial_scale_ * u / h^{3/2}
  double mu_rest_;         // friction at rest: min(tan zeta, mu(0+))
  // Work arrays, cell j at index j + ghost (one Rhs per integrator; not shared between threads).
  static constexpr std::size_t ghost = stencil_radius;
  mutable std::vector<double> h_, q_, u_, slope_h_, slope_q_, inertial_, mu_, face_flux_h_,
      face_flux_q_;
};

}  // namespace granbench::depthavg

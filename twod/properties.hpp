// Material properties of the two-phase mixture from the volume fraction f and the flow
// (properties.cpp): face densities and the mu(I) viscosity with its regularisation.
#pragma once

#include <span>

#include "common/mu_curves.hpp"
#include "twod/fields.hpp"
#include "twod/grid.hpp"
#include "twod/parameters.hpp"

namespace granbench::twod {

struct GranularViscosity {
  double eta = 0.0;            // the secant viscosity (2.11) [Pa s]
  double tangent_ratio = 1.0;  // Gamma / mu, in [0, 1]
};

class ViscosityModel {
 public:
  explicit ViscosityModel(const Rheology& r);
  // Inertial number (2.8) from the pressure (clipped at 0) and |D|; +inf where p <= 0.
  double inertial_number(double p, double D) const;
  // Its prefactor 2 d sqrt(rho_*): I = prefactor |D| / sqrt(p) where p > 0.
  double inertial_number_prefactor() const { return d_over_sqrt_rho_; }
  // Granular viscosity (2.11) with p clipped at 0, |D| floored and eta in [eta_min, eta_max].
  double granular(double p, double D) const;
  // The same with its tangent ratio Gamma/mu (Gamma = I mu'(I)): d(eta |D|)/d|D| = eta Gamma/mu,
  // the stiffness of the stress against a change of |D| along D, relative to the secant eta. 1
  // where eta does not depend on |D| (capped, floored, |D| at its floor, p <= 0, Newtonian).
  GranularViscosity granular_with_tangent(double p, double D) const;
  // The viscosity and its tangent of a mixture of granular fraction f (light fluid where f <= 0)
  // at pressure p and strain rate |D|, when the tangent direction carries the share `weight` of
  // |D|^2 (properties.cpp): at every point of a range, in loops the compiler vectorises. All six
  // spans have one size.
  void mixture_with_tangent_many(std::span<const double> f, std::span<const double> p,
                                 std::span<const double> D, std::span<const double> weight,
                                 std::span<double> eta, std::span<double> eta_tangent) const;
  // The mixture viscosity of a cell holding granular fraction f.
  double mix(double f, double eta_g) const;
  // The tangent of the mixture viscosity when eta_g has the tangent eta_gt.
  double mix_tangent(double f, double eta_g, double eta_gt) const;
  const MuCurve& curve() const { return curve_; }
  const Rheology& rheology() const { return r_; }

 private:
  Rheology r_;
  MuCurve curve_;
  double d_over_sqrt_rho_;  // 2 d / sqrt(1/rho_*) prefactor pieces of (2.8)
};

// rho at the u- and w-faces from f (arithmetic average of the adjacent cells).
void update_densities(const Grid& g, const std::vector<double>& f, const Rheology& r,
                      Properties& props);
// eta at cell centres and corners (and I at centres) from u, w, f and the pressure p_eta that
// mu(I) sees (the solver's: viscosity_pressure.hpp, the grains' effective pressure by default),
// with the tangent viscosities of the viscous step (properties.cpp).
void update_viscosity(const Grid& g, const Fields& s, const std::vector<double>& p_eta,
                      const ViscosityModel& model, Properties& props);

}  // namespace granbench::twod

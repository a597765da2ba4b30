// Scaled coefficients of the Bagnold (5.4)-(5.5) and Nusselt base states for the 2D linear
// stability operator; see analysis/linear2d/base_state.hpp for the formulas.
#include "analysis/linear2d/base_state.hpp"

#include <cmath>
#include <stdexcept>

namespace granbench::linear2d {

double LinearBaseState::U0(double z) const {
  if (profile == BaseProfile::Nusselt) return 3.0 * z - 1.5 * z * z;
  const double d = overburden;  // (5.5) over u_bar_0, for a layer 1 + d deep cut at z = 1
  return (5.0 / 3.0) * (std::pow(1.0 + d, 1.5) - std::pow(1.0 - z + d, 1.5));
}

double LinearBaseState::dU0(double z) const {
  if (profile == BaseProfile::Nusselt) return 3.0 * (1.0 - z);
  return 2.5 * std::sqrt(1.0 - z + overburden);  // d(5.5)/dz: I_zeta sqrt(p0/rho_*)/d, scaled
}

LinearBaseState mu_i_base_state(const SteadyState& s, const MuCurve& curve) {
  LinearBaseState b;
  b.profile = BaseProfile::Bagnold;
  b.F = s.Fr;
  b.mu = std::tan(s.zeta);
  b.Gamma = s.I_zeta * curve.dmu_dI(s.I_zeta);
  b.q = b.mu - 0.5 * b.Gamma;  // (3.3b)
  b.eta_n0 = 0.4 * b.mu;       // mu p0 / |dU0/dz| = (2 mu/5) sqrt(1 - z)   (2.11)
  b.eta_s0 = 0.4 * b.Gamma;    // (I mu'/mu) eta_n: the tangent viscosity, along A in (3.2)
  b.beta = 0.5;
  return b;
}

LinearBaseState newtonian_film_base_state(double F, double zeta_rad) {
  if (!(F > 0.0) || !(zeta_rad > 0.0))
    throw std::invalid_argument("Newtonian film needs F > 0 and a positive slope");
  LinearBaseState b;
  b.profile = BaseProfile::Nusselt;
  b.F = F;
  b.mu = std::tan(zeta_rad);
  b.eta_n0 = b.mu / 3.0;  // nu u_bar/(g cos zeta h^2) with u_bar = g sin zeta h^2/(3 nu)
  b.eta_s0 = b.mu / 3.0;
  b.beta = 0.0;
  return b;
}

double newtonian_film_reynolds(const LinearBaseState& b) {
  return 3.0 * b.F * b.F / b.mu;
}

}  // namespace granbench::linear2d

// Short-wave resolution study of the largest growth rate, flagging an ill-posed base state
// (analysis/linear2d/ill_posedness.hpp).
#include "analysis/linear2d/ill_posedness.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/linear2d/linear_stability_2d.hpp"
#include "common/ill_posedness.hpp"

namespace granbench::linear2d {

IllPosednessReport probe_ill_posedness(const SteadyState& s, const MuCurve& curve,
                                       const IllPosednessProbe& probe) {
  IllPosednessReport r;
  const double mu = curve.mu(s.I_zeta);
  r.C = ill_posedness_C(mu, s.I_zeta * curve.dmu_dI(s.I_zeta));  // (3.9)
  r.C_positive = r.C > 0.0;
  r.k_hat = probe.k_hat;
  r.N1 = probe.N;
  r.N2 = 2 * probe.N;
  const LinearBaseState b = mu_i_base_state(s, curve);
  r.growth_hat_N1 = spectrum(b, probe.k_hat, r.N1).front().real();
  r.growth_hat_N2 = spectrum(b, probe.k_hat, r.N2).front().real();
  const double rate = s.u_mean / s.h0;  // (7.13a)
  r.growth_rate_N1 = r.growth_hat_N1 * rate;
  r.growth_rate_N2 = r.growth_hat_N2 * rate;
  const double change =
      std::abs(r.growth_hat_N2 - r.growth_hat_N1) / std::max(std::abs(r.growth_hat_N2), 1e-12);
  r.ill_posed_base_state = r.growth_hat_N2 > 0.0 && change > probe.tolerance;
  std::ostringstream msg;
  msg << "C(I_zeta) = " << r.C << (r.C_positive ? " > 0" : " <= 0")
      << "; largest growth at k_hat = " << r.k_hat << ": " << r.growth_rate_N1
      << " 1/s (N = " << r.N1 << "), " << r.growth_rate_N2 << " 1/s (N = " << r.N2 << ")";
  msg << (r.ill_posed_base_state
              ? ": growth rises without converging as N grows; the base state is ill posed"
              : ": converged; no sign of ill posedness");
  r.message = msg.str();
  return r;
}

}  // namespace granbench::linear2d

// Numerical signature of an ill-posed base state in the 2D linear stability problem.
//
// When C(I_zeta) > 0 (3.7)-(3.9), the local growth rate (3.6) of a perturbation with wavevector
// xi is positive and grows like |xi|^2 for xi in a cone of oblique directions. At a fixed
// streamwise k the vertical wavenumbers that fit that cone are bounded (~ k), so the collocation
// eigenvalues still converge in N at long waves (for Jop at 28.5 deg, k_hat = 0.31: 1.4155e-3 at
// N = 48, 64 and 96). The blow-up shows at short waves, where the cone reaches the vertical
// wavenumbers that N more collocation points add: there the largest growth rate keeps rising as N
// is doubled (Jop, k_hat = 30: 1.36, 9.9, 18 at N = 32, 64, 96), while for a well-posed state it
// converges to a negative value. probe_ill_posedness computes that growth at N and 2N.
#pragma once

#include <string>

#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"

namespace granbench::linear2d {

struct IllPosednessProbe {
  double k_hat = 30.0;      // short wave, k h0
  int N = 32;               // and 2N
  double tolerance = 0.05;  // relative change N -> 2N that still counts as converged
};

struct IllPosednessReport {
  double C = 0.0;           // (3.9) at I_zeta
  bool C_positive = false;  // ill posed by (3.7)
  double k_hat = 0.0;
  int N1 = 0, N2 = 0;
  double growth_hat_N1 = 0.0;  // largest Re(lambda_hat) at N1, N2 (scaled (7.13))
  double growth_hat_N2 = 0.0;
  double growth_rate_N1 = 0.0;  // the same in 1/s
  double growth_rate_N2 = 0.0;
  bool ill_posed_base_state = false;  // positive growth that does not converge in N
  std::string message;
};

IllPosednessReport probe_ill_posedness(const SteadyState& s, const MuCurve& curve,
                                       const IllPosednessProbe& probe = {});

}  // namespace granbench::linear2d

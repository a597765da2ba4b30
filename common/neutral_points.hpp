// Neutral inertial numbers and neutral stability curves (Barker & Gray 2017, §3-§4).
//
// The neutral inertial numbers I_N are the roots of C(I) (3.9) along a curve; between them the
// sign of C says where the equations are well posed. The neutral curves
//
//   I_pm^N(mu) = A_pm exp[f_pm(mu)],                                                  (4.3)
//   f_+ =  sqrt(4-2mu^2)/(2mu^2) + ln mu - 1/2 ln(sqrt(4-2mu^2) + 2) - 1/mu^2,          (4.4)
//   f_- = -sqrt(4-2mu^2)/(2mu^2) + 1/2 ln(sqrt(4-2mu^2) + 2) - 1/mu^2,                  (4.5)
//
// solve dmu/dI = (1/I) mu/(16+mu^2) (8 + 2mu^2 +- 4 sqrt(4 - 2mu^2))  (4.2), and are real for
// mu <= sqrt(2). I_max = sqrt(2) I2N exp(-f_-(mu(I2N)) - 1/2) bounds every well-posed curve.
#pragma once

#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "common/mu_curves.hpp"

namespace granbench {

// Roots of C(I) for a curve given as functions mu(I) and dmu/dI, found by scanning I on a
// logarithmic grid over [I_lo, I_hi] for sign changes and refining each with GSL Brent.
std::vector<double> neutral_points(const std::function<double(double)>& mu,
                                   const std::function<double(double)>& dmu_dI, double I_lo = 1e-12,
                                   double I_hi = 1e3);

double ill_posedness_C(const MuCurve& curve, double I);

struct WellPosedness {
  std::vector<double> neutral;                       // all roots of C, ascending
  std::vector<std::pair<double, double>> intervals;  // [lo, hi] where C <= 0; lo = 0 when
                                                     // C <= 0 down to the scan floor
  std::optional<double> I1N, I2N;                    // lower/upper neutral points
  double I_max_wellposed = 0.0;                      // largest well-posed I
};
WellPosedness analyse_well_posedness(const MuCurve& curve);

// (4.4)-(4.5); require 0 < mu <= sqrt(2).
double neutral_f_plus(double mu);
double neutral_f_minus(double mu);
// dmu/dI of the neutral curves, (4.2); sign +1 or -1 selects the branch.
double neutral_slope(double mu, double I, int sign);
// A_pm through an anchor point (I_a, mu_a), and I_pm^N(mu) (4.3).
struct NeutralCurve {
  double A = 0.0;
  int sign = +1;
  double I_of_mu(double mu) const;
};
NeutralCurve neutral_curve_through(double I_anchor, double mu_anchor, int sign);
// I_max from the upper neutral point of the Jop-type curve (§4).
double I_max_from(double I2N, double mu_at_I2N);

}  // namespace granbench

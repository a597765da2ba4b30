// The well-posedness condition of the incompressible mu(I) equations (Barker et al. 2015,
// restated as (3.7)-(3.9) in Barker & Gray 2017):
//
//   C = 4 (I mu'/mu)^2 - 4 (I mu'/mu) + mu^2 (1 - I mu'/(2 mu))^2,      (3.9)
//
// C > 0: ill posed (3.7); C <= 0: well posed (3.8). Written on (mu, I mu') alone, so it serves
// any curve and also the curve constructors that need their own neutral points.
#pragma once

namespace granbench {

// (3.9) from mu and the logarithmic slope I*dmu/dI.
inline double ill_posedness_C(double mu, double I_dmu) {
  const double x = I_dmu / mu;
  const double y = 1.0 - 0.5 * x;
  return 4.0 * x * x - 4.0 * x + mu * mu * y * y;  // (3.9)
}

}  // namespace granbench

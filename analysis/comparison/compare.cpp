// The exact theories of the comparison; see compare.hpp.
#include "analysis/comparison/compare.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/linear2d/linear_stability_2d.hpp"
#include "analysis/theory/dispersion.hpp"

namespace granbench {

Theories exact_theories(const ChuteCase& c, bool with_2d) {
  const MuCurve curve = c.make_curve();
  const SteadyState base = steady_state(curve, degrees_to_radians(c.angle_deg), c.h0);
  Theories t;
  const DispersionMode d1 = dispersion_mode(base, 1.0, c.Lx);    // (7.11)
  const DispersionMode d54 = dispersion_mode(base, 1.25, c.Lx);  // chi = 5/4
  t.k_hat = d1.k_hat;
  t.exact = {d1.growth_rate, d1.phase_speed};
  t.exact_bagnold = {d54.growth_rate, d54.phase_speed};
  t.exact_2d = {NAN, NAN};
  t.exact_2d_convergence = NAN;
  if (!with_2d) return t;
  const Linear2DResult lin = linear_stability_2d(base, curve, c.Lx);
  t.exact_2d = {lin.surface.growth_rate, lin.surface.phase_speed};
  t.exact_2d_convergence = lin.surface.relative_difference;
  return t;
}

}  // namespace granbench

// The 2D solver's parameters from a chute case and the 2D settings; see twod_settings.hpp.
#include "analysis/comparison/twod_settings.hpp"

#include "twod/run.hpp"

namespace granbench {

twod::SolverParams twod_solver_params(const ChuteCase& c, const TwodSettings& s) {
  twod::SolverParams p;
  p.zeta = degrees_to_radians(c.angle_deg);
  twod::Rheology& r = p.rheology;
  r.material = c.material;
  r.curve = c.curve;
  r.h0_for_curve = c.h0;
  r.eta_max = s.eta_max;
  r.eta_min = s.eta_min;
  r.D_min = s.D_min;
  r.rho_light = s.rho_light;
  r.eta_light = s.eta_light;
  r.mixing = s.mixing;
  p.cfl = s.cfl;
  p.dt_max = s.dt_max;
  p.solver_tolerance = s.tolerance;
  p.viscosity_passes = s.viscosity_passes;
  p.threads = s.threads;
  try {
    p.velocity_limit = twod::divergence_speed_limit(c.steady().u_surface);
  } catch (const CurveRangeError&) {
    // no steady flow on this slope: the solver's default limit
  }
  return p;
}

}  // namespace granbench

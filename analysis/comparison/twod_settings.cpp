// The 2D solver's parameters from a chute case and the 2D settings; see twod_settings.hpp.
#include "analysis/comparison/twod_settings.hpp"

#include <cmath>

#include "analysis/comparison/growth_deficit_law.hpp"
#include "twod/run.hpp"

namespace granbench {

TwodSettings TwodSettings::refined_across(double wavelength, const SteadyState& base,
                                          double exact_growth, double a0, double t_end) const {
  TwodSettings r = *this;
  r.nz = cells_across(wavelength, base.h0);
  if (!(exact_growth > 0.0)) return r;
  auto meets_the_aim = [&](const TwodSettings& t) {
    const double dz = t.domain_height(base.h0) / t.nz;
    return expected_twod_growth_deficit(base, dz, wavelength) <=
           aimed_growth_deficit * exact_growth;
  };
  if (meets_the_aim(r)) return r;
  const bool stays_small = a0 * std::exp(exact_growth * t_end) <= small_wave_over_h0 * base.h0;
  const int most = multiple_of_16(static_cast<int>(std::ceil(max_law_refinement * nz)));
  if (Lz_over_h0 == 0.0 && stays_small && light_layer_over_h0 > near_cutoff_light_layer) {
    // the fewest rows of the thin domain with cells no taller than the wavelength's grid's
    const double tallest = r.domain_height(base.h0) / r.nz;
    r.light_layer_over_h0 = near_cutoff_light_layer;
    for (r.nz = 16; r.nz < most && r.domain_height(base.h0) / r.nz > tallest;) r.nz += 16;
  }
  for (; r.nz < most; r.nz += 16)  // (the domain's height follows nz when the surface is mid-cell)
    if (meets_the_aim(r)) return r;
  return r;  // the cap: the warnings say what is left (analysis/cli/physics_warnings.hpp)
}

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
  p.consistent_momentum = s.consistent_momentum;
  p.threads = s.threads;
  try {
    p.velocity_limit = twod::divergence_speed_limit(c.steady().u_surface);
  } catch (const CurveRangeError&) {
    // no steady flow on this slope: the solver's default limit
  }
  return p;
}

std::vector<std::pair<std::string, double>> named_values(const TwodSettings& s) {
  return {{"nx", double(s.nx)},
          {"nz", double(s.nz)},
          {"Lz_over_h0", s.Lz_over_h0},
          {"light_layer_over_h0", s.light_layer_over_h0},
          {"eta_max", s.eta_max},
          {"eta_min", s.eta_min},
          {"D_min", s.D_min},
          {"rho_light", s.rho_light},
          {"eta_light", s.eta_light},
          {"mixing", double(static_cast<int>(s.mixing))},
          {"cfl", s.cfl},
          {"dt_max", s.dt_max},
          {"tolerance", s.tolerance},
          {"viscosity_passes", double(s.viscosity_passes)},
          {"consistent_momentum", s.consistent_momentum ? 1.0 : 0.0},
          {"chebyshev_N", double(s.chebyshev_N)},
          {"frame_fraction", s.frame_fraction},
          // How nx becomes the cells along another length (cells_along): 3, at least nx cells and
          // at most their dx at 8 cm, rounded up to a multiple of 16 (since 5 December); 2 did
          // not round (since 3 December), and a sweep file without it kept the dx alone. Points
          // stored under another rule are not resumed on the new grids.
          {"nx_rule", 3.0},
          // How nz becomes the cells across the layer for a shorter wave (cells_across): 1, the
          // preset's nz refined for waves under 7.5 h0 (since 5 December); a sweep file without
          // it kept nz at every length, and its short points are not resumed on the new grids.
          // 2: and raised by the deficit law near the 2D cutoff, to aimed_growth_deficit of the
          // exact growth (since 6 December); a file of rule 1 kept at most twice the preset's nz.
          // 3: and, where the law refines a wave that stays small, a light layer of h0/4 (since
          // 6 December, thirty-sixth session); rule 2 kept h0 of it.
          {"nz_rule", 3.0},
          {"aimed_growth_deficit", s.aimed_growth_deficit}};
}

}  // namespace granbench

// The 2D model's settings for a chute case (chute_case.hpp): grid, light fluid, the viscosity
// cap and floors, the interface viscosity rule and the time-step and solver controls. One type
// for every caller (`run --model twod`, compare, sweep and the layer cases), and one function
// that turns a case and these settings into the solver's parameters.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "analysis/comparison/chute_case.hpp"
#include "twod/grid.hpp"
#include "twod/parallel.hpp"
#include "twod/parameters.hpp"

namespace granbench {

struct TwodSettings {
  int nx = 160, nz = 32;
  double Lz_over_h0 = 0.0;  // 0: about 1 + light_layer_over_h0, the surface mid-cell
  // The light fluid's depth above the grains, in h0, of a domain whose height follows nz
  // (Lz_over_h0 = 0; twod::mid_cell_domain_height). refined_across thins it near the 2D cutoff.
  double light_layer_over_h0 = 1.0;
  double eta_max = twod::Rheology{}.eta_max;  // granular viscosity cap [Pa s] (docs/design.md §8)
  double eta_min = twod::Rheology{}.eta_min;  // granular viscosity floor [Pa s]
  double D_min = twod::Rheology{}.D_min;      // floor on |D| [1/s]
  double rho_light = twod::Rheology{}.rho_light, eta_light = twod::Rheology{}.eta_light;
  twod::ViscosityMixing mixing = twod::Rheology{}.mixing;    // in interface cells
  double cfl = twod::SolverParams{}.cfl;                     // Courant number per direction
  double dt_max = twod::SolverParams{}.dt_max;               // [s]
  double tolerance = twod::SolverParams{}.solver_tolerance;  // relative residual of linear solves
  int viscosity_passes = twod::SolverParams{}.viscosity_passes;  // Picard passes for eta per step
  // momentum carried by the VOF step's mass fluxes (twod/parameters.hpp)
  bool consistent_momentum = twod::SolverParams{}.consistent_momentum;
  int chebyshev_N = 32;  // resolution of the eigenmode used for seeding
  // The grid moves downslope at this fraction of the steady surface speed (twod/frame.hpp): at
  // 0.5 the largest |u| relative to the grid, and so the number of steps, about halves. 0: the
  // lab frame. The output is in the lab frame either way.
  double frame_fraction = 0.5;
  // Threads of the 2D solver: by default those of the thread that makes the settings
  // (OMP_NUM_THREADS or --threads), which the run keeps on whichever thread it is started.
  int threads = twod::thread_count();
  // nx is for the reference length Lx = 8 cm of the presets (dx = 0.5 mm at 160 cells). Over
  // another length, compare and sweep keep at least nx cells along the domain, which holds one
  // wavelength of the seeded wave, and at most that dx: a short wave keeps the preset's cells per
  // wavelength (the 2 cm wave had 40 cells with dx alone and grew 34 % below the 2D theory, 16 %
  // with 160: docs/twod-validation.md §2), and a long domain the preset's dx. The count is
  // rounded up to a multiple of 16, as nz is: the pressure multigrid halves the grid while both
  // counts are even, and a column count it cannot halve (195 at 9.7 cm) left it smoothing on the
  // fine grid, 3.5 times slower a step (docs/performance.md, twenty-eighth session).
  static constexpr double reference_length = 0.08;
  int cells_along(double Lx) const {
    return multiple_of_16(std::max(nx, static_cast<int>(std::lround(nx * Lx / reference_length))));
  }
  // n rounded up to a multiple of 16: a count the pressure multigrid halves four times.
  static int multiple_of_16(int n) { return 16 * ((n + 15) / 16); }
  // Across the layer, compare and sweep keep the preset's nz for waves of
  // longest_wave_to_refine h0 and longer, and refine a shorter wave's grid in proportion to
  // 1 / wavelength, so that dz stays at most wavelength / (cells per h0 x 7.5): 240 cells per
  // wavelength at the default 32 per h0, up to twice the preset's cells. The surface layer's
  // error at fixed cells per h0 grows fast as the wave shortens (order 1.4 in dz; at 32 per h0
  // -3.1 % at 10 h0, -11.4 % at 5 h0, and the slow branch at 5 h0 -10.9 %:
  // docs/twod-validation.md §3). nz is rounded up to a multiple of 16, which the pressure
  // multigrid coarsens four times.
  static constexpr double longest_wave_to_refine = 7.5;  // in h0
  static constexpr double max_refinement = 2.0;
  static double refinement_across(double wavelength, double h0) {
    return std::clamp(longest_wave_to_refine * h0 / wavelength, 1.0, max_refinement);
  }
  int cells_across(double wavelength, double h0) const {
    const double r = refinement_across(wavelength, h0);
    if (r <= 1.0) return nz;
    // (less 1.6e-8: a product that round-off lifts just above a multiple of 16 stays on it)
    return multiple_of_16(static_cast<int>(std::ceil(nz * r - 1.6e-8)));
  }
  // Near the 2D cutoff the growth falls to zero while the surface layer's deficit does not: the
  // 1.5 cm wave of the section 7 case grew 19.8 % under the 2D theory on the 64 cells per h0 of
  // the rule above, 8.0 % under on 128 (docs/twod-validation.md §3). So compare, sweep and `run`
  // refine further where the deficit law (growth_deficit_law.hpp) expects more than
  // aimed_growth_deficit of the wave's exact 2D growth: the fewest cells across (a multiple of
  // 16, from cells_across above) at which it expects no more, at most max_law_refinement times
  // nz. 7.5 % for the default presets leaves the law's scatter (its coefficient 0.15-0.20) inside
  // the 10 %; the coarse preset aims at 3/4 of its 25 %. Every wave whose law deficit on
  // the rule above is within the aim keeps that grid (3 cm and longer, 2 and 2.5 cm at 28.5
  // degrees and 4 mm).
  double aimed_growth_deficit = 0.075;
  // The cap bounds a point's cost: six times the preset's rows, 384 at the default preset. Under
  // the thin light layer below that is 306.5 cells per h0, on which the 1.4 cm wave (1.5 % above
  // the cutoff) grew 0.14 % above the 2D theory (0.66 % under with the default light fluid since
  // the fiftieth session, which no longer lifts it); on four times (204.5 per h0) it was 12 %
  // under (docs/twod-validation.md §3, "A thin light layer near the cutoff").
  static constexpr double max_law_refinement = 6.0;
  // Where the law refines, a run whose wave stays small also takes a light layer of
  // near_cutoff_light_layer h0 instead of h0: its rows then go to the grains, and the light
  // fluid's own effect, an absolute shift of the growth (exact light-layer theory: -0.0038 1/s at
  // 1.4 cm under h0 of it), shrinks where the growth itself is small (-5.5 % of the growth at
  // 1.4 cm under h0, +0.6 % under h0/4; docs/twod-validation.md §3, "A thin light layer near the
  // cutoff"). "Small": the seed grown at the exact rate to the end of the run stays within
  // small_wave_over_h0 h0, five times its height under the thin layer.
  static constexpr double near_cutoff_light_layer = 0.25;
  static constexpr double small_wave_over_h0 = 0.05;
  // These settings with nz (and the light layer) for a wave of this length [m] and exact 2D
  // growth rate [1/s] on this base state, seeded with amplitude a0 [m] and run for t_end [s]:
  // cells_across(wavelength, h0) where the growth is not positive (or NaN: not known) or where
  // that grid meets the aim; otherwise raised by the deficit law as above, on the thin light
  // layer when the wave stays small and the domain's height is not given (Lz_over_h0 = 0).
  TwodSettings refined_across(double wavelength, const SteadyState& base, double exact_growth,
                              double a0, double t_end) const;
  double domain_height(double h0) const {
    return Lz_over_h0 > 0.0 ? Lz_over_h0 * h0
                            : twod::mid_cell_domain_height(h0, nz, 1.0 + light_layer_over_h0);
  }
};

// Every setting by name (the mixing rule by its enum value), for the stored settings of a sweep
// and the attributes of compare's file ("twod_" + name): one list, so none of them misses one.
std::vector<std::pair<std::string, double>> named_values(const TwodSettings& s);

// The solver's parameters for the case's material, curve, slope and depth and these settings;
// the only place they are assembled from user input. The divergence limit on |u| is ten times
// the surface speed of the case's steady flow (twod/run.hpp), or the solver's default on a
// slope with no steady flow (the decelerating layer of §5.2).
twod::SolverParams twod_solver_params(const ChuteCase& c, const TwodSettings& s);

}  // namespace granbench

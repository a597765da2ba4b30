// Warnings about a 2D run that a user should see before trusting its numbers, printed on stderr
// ("granbench: warning: ...", also with --quiet) and listed in the JSON under "warnings":
//  - the base state is ill posed: C(I_zeta) > 0 (3.9), where the incompressible mu(I) equations
//    amplify short waves without bound and results depend on the grid (§3-§5);
//  - the grid has fewer than 32 cells per h0, the resolution below which the measured 2D growth
//    rate is more than 10 % under the exact 2D theory (docs/twod-validation.md, the README);
//  - the wave is shorter than 7.5 h0 on fewer cells per h0 than the default grids give it
//    (TwodSettings::cells_across: 32 per h0 refined as 7.5 h0 / wavelength, up to 64): the surface
//    layer's error grows as the wave shortens (order 1.4 in dz), and at 32 cells per h0 the
//    section 7 case's wave of 5 h0 is 11 % under the theory, its slow branch too
//    (docs/twod-validation.md §3);
//  - the exact 2D growth rate is small against the error the grid is expected to carry (near a
//    cutoff, where the growth falls to zero): twod_growth_accuracy_warning. The default grids
//    refine there by the same law (TwodSettings::refined_across with the growth), up to six
//    times the preset's rows, so on them it names only the waves nearest the cutoff.
// And one about cost, twod_grid_cost_warning: a grid the pressure multigrid cannot coarsen.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/comparison/growth_deficit_law.hpp"
#include "analysis/comparison/twod_settings.hpp"
#include "common/steady_state.hpp"

namespace granbench::cli {

inline constexpr double kTrustedCellsPerDepth = 32.0;

// wavelength: the seeded wave's length [m] (Lx / mode).
std::vector<std::string> twod_warnings(const SteadyState& base, double dz, double wavelength);
// The deficit law (kGrowthDeficitCoefficient, kGrowthDeficitOrder, expected_twod_growth_deficit)
// is in analysis/comparison/growth_deficit_law.hpp.

// Whether a domain of this height [m] holds less than h0/2 of light fluid above the grains: the
// thin layer (h0/4) of the grids near the 2D cutoff (TwodSettings::refined_across), or a --Lz as
// low. The deficit law was measured under h0 of light fluid; under the thin layer the measured
// deficits were 1.3 times smaller than it says at 127.5 cells per h0 (1.5 cm) and 8 to 14 times
// at 306.5 (1.372 to 1.4 cm; 15 to 90 times with the former, heavier light fluid), and its order
// did not hold (docs/twod-validation.md §3, "Down to the cutoff" and "The lighter light fluid as
// the default").
bool under_thin_light_layer(double domain_height, double h0);

// When the law's deficit is more than 10 % of a positive exact 2D growth rate (a wave near the 2D
// cutoff, or a coarse grid), a warning with the growth, the expected deficit and the cells per h0
// that would bring it to 5 %, as the --nz that gives them on a domain of this height (a multiple
// of 16, as the default grids); nothing otherwise. Under a thin light layer
// (under_thin_light_layer), on a grid as fine as those measured there (127.5 cells per h0 or
// more), the warning gives the deficits measured there instead of the law's cells, which would be
// far more than needed.
std::optional<std::string> twod_growth_accuracy_warning(const SteadyState& base, double dz,
                                                        double wavelength, double exact_growth,
                                                        double domain_height);

// When --extrapolate is asked of a grid under a thin light layer (under_thin_light_layer: the
// near-cutoff rule's, TwodSettings::refined_across, or a --Lz as low), a warning that the deficit
// law's order, on which the extrapolation rests, was measured under h0 of light fluid and failed
// under the thin layer at 1.4 cm (the pair converged at order 5.5 and the extrapolation overshot to
// +10.7 % from -0.41 % measured; with the former light fluid order 5.3, +10.95 % from +0.14 %;
// docs/twod-validation.md §3); nothing otherwise.
std::optional<std::string> thin_layer_extrapolation_warning(const TwodSettings& grid, double h0);

// A 2D step above the VOF's 1/2 (--cfl, allowed up to 1) on a sine start: the decay of the short
// waves the sine seeds moves with the step far more than the fundamental's growth does, and it
// reaches the growth fitted after the transient (docs/twod-validation.md §2, "Steps above half a
// cell": 160 x 16 measures -13.1 % at cfl 0.8 against -6.75 % at 0.4); nothing for the eigenmode
// start, whose growth costs 0.6 % at 0.8, or for a step of 1/2 or less.
std::optional<std::string> large_step_sine_start_warning(double cfl, bool sine_start);

// When the pressure multigrid cannot coarsen an nx x nz grid of cells dx / dz = aspect to one it
// solves directly (an odd count, twod/pressure_multigrid.hpp), a warning that each step will
// cost several times more and the counts, rounded up to multiples of 16, that avoid it; nothing
// otherwise.
std::optional<std::string> twod_grid_cost_warning(int nx, int nz, double aspect);

// When the undisturbed surface h0 lies on a cell face of nz cells over domain_height (within 2 % of
// a cell), a warning with the --Lz that puts it mid-cell on the same nz; nothing otherwise. On a
// face the volume fractions fill the empty row above in thin films as the surface moves: a
// growing 8 cm wave loses 0.5 % of its rate, a damped 1.2 cm wave at 32 cells per h0 is damped
// 0.52 1/s too much where mid-cell gives 0.19, and a flat 0.7 mm layer kept a surface wave alive
// that the theory damps (docs/twod-validation.md §4, fifty-second session). The default grids put
// the surface mid-cell.
std::optional<std::string> surface_on_face_warning(double h0, double domain_height, int nz);

void print_warnings(const std::vector<std::string>& warnings);

}  // namespace granbench::cli

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
//    (docs/twod-validation.md §3).
#pragma once

#include <string>
#include <vector>

#include "common/steady_state.hpp"

namespace granbench::cli {

inline constexpr double kTrustedCellsPerDepth = 32.0;

// wavelength: the seeded wave's length [m] (Lx / mode).
std::vector<std::string> twod_warnings(const SteadyState& base, double dz, double wavelength);
void print_warnings(const std::vector<std::string>& warnings);

}  // namespace granbench::cli

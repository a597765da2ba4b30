// The pressure at which the viscosity of the new time level is evaluated (viscosity_pressure.cpp).
#pragma once

#include <vector>

#include "twod/grid.hpp"
#include "twod/parameters.hpp"

namespace granbench::twod {

// p^n plus the change of the hydrostatic pressure between the column heights h^n and h^{n+1}
// (the surface before and after this step's VOF advection).
// Writes p_eta (resized to the cells).
void viscosity_pressure(const Grid& g, const SolverParams& params, const std::vector<double>& p,
                        const std::vector<double>& h_before, const std::vector<double>& h_after,
                        std::vector<double>& p_eta);

}  // namespace granbench::twod

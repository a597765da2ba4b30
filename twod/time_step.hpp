// Adaptive time step (time_step.cpp).
#pragma once

#include "twod/fields.hpp"
#include "twod/grid.hpp"
#include "twod/parameters.hpp"

namespace granbench::twod {

// The CFL-limited step for the state s, no more than dt_growth times the previous step.
double choose_time_step(const Grid& g, const Fields& s, const SolverParams& params,
                        double dt_previous);

}  // namespace granbench::twod

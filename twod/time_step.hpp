// Adaptive time step (time_step.cpp).
#pragma once

#include "fields.hpp"
#include "grid.hpp"
#include "parameters.hpp"

namespace granbench::twod {

// The CFL-limited step for the state s, no more than dt_growth times the previous step.
double choose_time_step(const Grid& g, const Fields& s, const SolverParams& params,
                        double dt_previous);

}  // namespace granbench::twod

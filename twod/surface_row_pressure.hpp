// The horizontal pressure force on partly filled u-faces (surface_row_pressure.cpp).
#pragma once

#include <vector>

#include "twod/grid.hpp"
#include "twod/parameters.hpp"

namespace granbench::twod {

// The correction, per u-face [N per unit width], to add to the predictor's pressure force
// -dz (p_i - p_{i-1}) so that a partly filled u-face feels the hydrostatic force on the grains it
// holds; zero where both cells are full or empty. f: the volume fractions of the new level.
// Writes `correction` (resized to the cells); the solver keeps it from step to step.
void surface_row_pressure_correction(const Grid& g, const SolverParams& params,
                                     const std::vector<double>& f, std::vector<double>& correction);
// The same, returned.
inline std::vector<double> surface_row_pressure_correction(const Grid& g,
                                                           const SolverParams& params,
                                                           const std::vector<double>& f) {
  std::vector<double> correction;
  surface_row_pressure_correction(g, params, f, correction);
  return correction;
}

}  // namespace granbench::twod

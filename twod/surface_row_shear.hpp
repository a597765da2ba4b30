// The shear-stress force on the w-faces around a partly filled surface row
// (surface_row_shear.cpp).
#pragma once

#include <vector>

#include "twod/fields.hpp"
#include "twod/grid.hpp"

namespace granbench::twod {

// The correction, per w-face [N per unit width], to add to the predictor's force on the w-faces
// just below and just above the surface row of each column, so that the x-derivative of the shear
// stress tau_xz acts over the heights the grains fill. f: the volume fractions of the new level;
// props: eta_n and gamma_n of the same level (the corner stress eta_n gamma_n). Zero everywhere
// else. Writes `correction` (resized to the w-faces); the solver keeps it from step to step.
void surface_row_shear_correction(const Grid& g, const std::vector<double>& f,
                                  const Properties& props, std::vector<double>& correction);

}  // namespace granbench::twod

// Piecewise-linear interface geometry (PLIC) in a unit square, after Scardovelli & Zaleski
// (2000). The interface in a cell is the line  m1 X + m2 Z = alpha  in cell-unit coordinates
// X, Z in [0, 1]; the fluid occupies  m1 X + m2 Z <= alpha  (m points out of the fluid). A
// physical normal (mx, mz) maps to (m1, m2) = (mx dx, mz dz), so anisotropic cells need nothing
// else.
//
//   plic_area(m1, m2, alpha)    fluid area below the line (the volume fraction it implies)
//   plic_alpha(m1, m2, c)       the inverse: the line constant holding volume fraction c
//   plic_rect_fraction(...)     fluid fraction inside the sub-rectangle [x0, x0 + wx] x
//                               [z0, z0 + wz] of the cell, relative to the sub-rectangle
#pragma once

namespace granbench::twod {

double plic_area(double m1, double m2, double alpha);
double plic_alpha(double m1, double m2, double c);
double plic_rect_fraction(double m1, double m2, double alpha, double x0, double wx, double z0,
                          double wz);

}  // namespace granbench::twod

// The co-moving frame of the 2D solver (frame.cpp): the grid moves downslope at U =
// Grid::frame_speed, so the solver's velocities are u - U and its positions x - U t. Every output
// is in the lab frame; these functions take the solver's per-column values and positions there.
//
// Why: the time step is set by the largest |u| per cell (time_step.cpp), and in the lab frame
// that is the surface speed u_s while the bed is at rest. At U = u_s / 2 the largest |u - U| is
// about u_s / 2, so the same Courant number allows about twice the step (docs/performance.md).
#pragma once

#include <vector>

#include "twod/grid.hpp"

namespace granbench::twod {

// How far the grid has moved at time t, wrapped into [0, Lx) [m].
double frame_offset(const Grid& g, double t);
// The lab position of grid position x at time t, wrapped into [0, Lx).
double lab_position(const Grid& g, double x, double t);

// Per-column values (at the column centres x_i = (i + 1/2) dx of the grid) taken to the same
// centres in the lab frame at time t: lab(x_i) = grid(x_i - U t), by periodic four-point
// (cubic) Lagrange interpolation, exact at whole-cell shifts. Its error on a Fourier mode of
// wavenumber k is O((k dx)^4): 2e-6 of the fundamental's amplitude at 160 cells.
std::vector<double> columns_in_lab_frame(const Grid& g, double t, const std::vector<double>& v);

// For fields written whole (snapshots): the lab frame holds grid column i at lab column
// (i + shift) mod nx, with its centre offset by `remainder` in [-dx/2, dx/2) from that column's
// centre. No interpolation, so the VOF field keeps its sharp interface.
struct ColumnShift {
  int shift = 0;
  double remainder = 0.0;
};
ColumnShift lab_column_shift(const Grid& g, double t);

}  // namespace granbench::twod

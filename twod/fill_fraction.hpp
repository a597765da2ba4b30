// When a cell's granular fraction counts as full, empty or cut by the surface.
#pragma once

#include <vector>

#include "twod/grid.hpp"

namespace granbench::twod {

// The VOF step leaves round-off in cells the surface only touches: wisps of 1e-30 to 1e-16 in the
// rows above a surface that lies on a cell face, and fractions of 1 - 1e-16 in the row below it
// (docs/twod-validation.md §4, "Wisps at a face"). The PLIC step does not cut such cells, and the
// surface treatment must not take them for the surface either: tested for exact 0 and 1, a wisp
// above a film switched the surface row's shear correction off in every column.
inline constexpr double kUncutFill = 1e-12;

inline bool is_empty(double f) {
  return f <= kUncutFill;
}
inline bool is_full(double f) {
  return f >= 1.0 - kUncutFill;
}
// A cell the surface cuts: neither empty nor full.
inline bool is_cut(double f) {
  return !is_empty(f) && !is_full(f);
}

// Row k of column i holds the surface of a graph h(x): cut, with a full cell below and an empty
// one above (the surface row that surface_row_shear.cpp and properties.cpp treat as such).
inline bool is_graph_surface_row(const Grid& g, const std::vector<double>& f, int i, int k) {
  return k > 0 && k < g.nz - 1 && is_cut(f[g.at(i, k)]) && is_full(f[g.at(i, k - 1)]) &&
         is_empty(f[g.at(i, k + 1)]);
}

}  // namespace granbench::twod

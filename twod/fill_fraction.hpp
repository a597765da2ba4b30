// When a cell's granular fraction counts as full, empty or cut by the surface.
#pragma once

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

}  // namespace granbench::twod

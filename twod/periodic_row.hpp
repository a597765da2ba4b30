// The columns of one row of the periodic grid with their left neighbours, in a loop the compiler
// vectorises: column 0, whose left neighbour is the last column, goes first on its own, and the
// rest run in one `omp simd` loop with the neighbour i - 1 (a wrap inside the loop would stop
// the vectoriser). Used by the row loops of properties.cpp, surface_row_pressure.cpp,
// projection.cpp and viscous_step.cpp.
#pragma once

#include <algorithm>

namespace granbench::twod {

// body(i_left, i) for every column i of [i_begin, i_end) of a row of nx columns, i_left = i - 1
// (nx - 1 for i = 0). body must write only column i's entries (the loop is marked simd).
template <class Body>
inline void for_columns_with_left(int nx, int i_begin, int i_end, Body&& body) {
  if (i_begin == 0 && i_end > 0) body(nx - 1, 0);
#pragma omp simd
  for (int i = std::max(i_begin, 1); i < i_end; ++i) body(i - 1, i);
}

}  // namespace granbench::twod

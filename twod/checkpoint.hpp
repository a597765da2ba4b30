// Checkpoint and restart of a 2D run (checkpoint.cpp): the staggered fields, the clock, the
// counters and the surface series so far, in one HDF5 file.
#pragma once

#include <string>

#include "fields.hpp"
#include "grid.hpp"
#include "solver.hpp"
#include "surface_series.hpp"

namespace granbench::twod {

struct Checkpoint {
  Grid grid;
  Fields state;
  long steps = 0;
  double dt_last = 0.0;
  double initial_volume = 0.0;
  SurfaceSeries series;
  WarmStart warm_start;  // empty in checkpoints written before it was saved
};

void write_checkpoint(const std::string& path, const Solver& solver, const SurfaceSeries& series);
// Throws std::runtime_error when the file is missing or incomplete.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace granbench::twod

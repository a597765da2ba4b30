// Checkpoint and restart of a 2D run (checkpoint.cpp): the staggered fields, the clock, the
// counters, the surface series so far, the times of the snapshots written so far and the physics
// of the run (slope, curve, material, depth, regularisation), in one HDF5 file. A checkpoint is
// written to a temporary name and renamed into place (H5Writer), so a process killed while
// writing leaves the previous checkpoint intact.
#pragma once

#include <string>
#include <vector>

#include "common/surface_series.hpp"
#include "twod/fields.hpp"
#include "twod/grid.hpp"
#include "twod/solver.hpp"

namespace granbench::twod {

struct Checkpoint {
  Grid grid;
  Fields state;
  long steps = 0;
  double dt_last = 0.0;
  double initial_volume = 0.0;
  SurfaceSeries series;
  WarmStart warm_start;                // empty in checkpoints written before it was saved
  std::vector<double> snapshot_times;  // the snapshots the run had written [s]
  // The physics as (name, value): the names are the options of `granbench run` that set them
  // (angle, curve, mu-s, ..., h0, eta-max, ...); curve and mixing as their enumerators' indices.
  std::vector<std::pair<std::string, double>> physics;
};

void write_checkpoint(const std::string& path, const Solver& solver, const SurfaceSeries& series,
                      const std::vector<double>& snapshot_times = {});
// Throws std::runtime_error when the file is missing or incomplete.
Checkpoint read_checkpoint(const std::string& path);

// Gives `solver`, built on c.state (check restart_mismatch first), the counters and the linear
// solvers' memory of the checkpoint, so that it continues the run bit for bit.
void resume_from(Solver& solver, const Checkpoint& c);

// The physics of a run with these parameters, in the checkpoint's naming.
std::vector<std::pair<std::string, double>> checkpoint_physics(const SolverParams& params);

// Why a run with `grid` and `params` cannot continue from `c`: the first parameter that differs
// ("angle: the checkpoint has 28.5, this run 25"), or an empty string. A restart with other
// physics would label the first part of the history with the wrong inputs.
std::string restart_mismatch(const Checkpoint& c, const Grid& grid, const SolverParams& params);

}  // namespace granbench::twod

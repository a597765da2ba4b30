// `granbench sweep --model twod|both`: the dispersion sweep over domain lengths with the 2D model
// (or both), on the resumable parallel engine of analysis/comparison/sweep.hpp. Each point is a
// run seeded with the eigenmode of the model's own exact theory, measured spectrally; the table
// sets each model beside its theory ((7.11) with the model's chi for depthavg, the 2D linear
// stability for twod). The depth-averaged-only sweep keeps its own tighter path (cmd_sweep.cpp).
#pragma once

#include <string>
#include <vector>

#include "cli_common.hpp"

namespace granbench::cli {

struct ModelSweepOptions {
  bool depthavg = false, twod = true;
  std::vector<double> Lx;
  unsigned jobs = 2;
  double t_end = 2.0;          // per point [s]
  int nx = 80, nz = 16;        // 2D grid
  std::size_t nx_depthavg = 256;
  double chi = 1.0;
};

void run_model_sweep(const FlowOptions& flow, const OutputOptions& output,
                     const ModelSweepOptions& o);

}  // namespace granbench::cli

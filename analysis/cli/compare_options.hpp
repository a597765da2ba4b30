// The options of `granbench compare` (cmd_compare.cpp): the flow, the domain, the seed, the run
// length, the grids and the depth-averaged frame. Parsing and validation only.
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>

#include "analysis/cli/cli_common.hpp"
#include "analysis/comparison/chute_case.hpp"
#include "analysis/comparison/twod_settings.hpp"

namespace granbench::cli {

struct CompareOptions {
  FlowOptions flow;
  OutputOptions output;
  double Lx = 0.08;
  double a0 = ChuteCase{}.a0;
  bool paper = false;
  std::string init = "eigenmode";
  double t_end = 2.0;
  double dt_out = 0.0;
  std::string resolution = "default";
  int nx = 0, nz = 0;                  // 2D grid; 0: from --resolution
  std::size_t nx_depthavg = 0;         // 0: from --resolution
  std::string frame_speed = "linear";  // depth-averaged frame: linear (co-moving) or 0 (lab)
  int viscosity_passes = 1;
  double twod_frame = 0.5;  // the 2D grid's speed / surface speed (TwodSettings::frame_fraction)
  double cfl = TwodSettings{}.cfl;  // the 2D time step's Courant number per direction
  bool extrapolate = false;         // the 2D growth also from half the cells across the layer
};

// Adds the options of this file's struct (not the flow and output options) to `sub`.
void add_compare_options(CLI::App& sub, CompareOptions& o);

}  // namespace granbench::cli

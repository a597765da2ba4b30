// `granbench run --model twod`: the 2D two-phase mu(I) solver's own options and entry point
// (run_twod.cpp). The options shared by every model (angle, h0, curve, Lx, nx, a0, t_end, ...)
// are in RunOptions (run_model.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "parameters.hpp"
#include "run_model.hpp"

namespace granbench::cli {

struct TwodOptions {
  int nz = 64;                  // cells along z
  double Lz = 0.0;              // domain height [m]; 0: ~2 h0, h0 mid-cell (mid_cell_domain_height)
  double eta_max = 2.0;         // granular viscosity cap [Pa s]
  double eta_min = 1e-3;        // granular viscosity floor [Pa s]
  double D_min = 1e-6;          // floor on |D| [1/s]
  double rho_light = twod::Rheology{}.rho_light;  // light-fluid density [kg/m^3]
  double eta_light = twod::Rheology{}.eta_light;  // light-fluid viscosity [Pa s]
  std::string mixing = "arithmetic";
  double cfl = 0.4;
  int viscosity_passes = 1;
  double dt_max = 1e-3;         // [s]
  double tolerance = 1e-10;     // relative residual of the linear solves
  double dt_snapshot = 0.0;     // interval of the 2D field snapshots [s]; 0: t_end/10
  std::string checkpoint;       // written on SIGINT/SIGTERM; default <out>.checkpoint.h5
  std::string restart;          // continue from this checkpoint
};
void add_twod_options(CLI::App& app, TwodOptions& o);

// Runs the 2D model; prints the table or JSON, writes --out (+ .xdmf). Throws CommandFailed
// after saving what was computed when interrupted (exit 130, with a checkpoint) or diverged
// (exit 3).
void run_twod(const RunOptions& run, const TwodOptions& model);

}  // namespace granbench::cli

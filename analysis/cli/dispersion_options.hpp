// The options of `granbench dispersion` (cmd_dispersion.cpp): the flow, the domain lengths, the
// theory and its resolution, and the 2D solver's light layer. Parsing and validation only.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/cli/cli_common.hpp"
#include "analysis/linear2d/light_layer.hpp"
#include "twod/parameters.hpp"

namespace granbench::cli {

enum class Theory { DepthAvg, DepthAvgBagnold, TwoD };

struct DispersionOptions {
  FlowOptions flow;
  OutputOptions output;
  std::vector<double> Lx;
  std::string theory = "depthavg";
  int resolution = 32;  // Chebyshev intervals of --theory twod
  // --light-layer: the 2D solver's light fluid above the grains, defaults from the solver.
  bool light_layer = false;
  double rho_light = twod::Rheology{}.rho_light;
  double eta_light = twod::Rheology{}.eta_light;
  double Lz = 0.0;  // [m]; 0: 2 h0, the solver's default
};

// The light layer of the options, validated (one-line errors naming the option).
std::optional<linear2d::LightLayer> light_layer(const DispersionOptions& o, Theory theory);
Theory parse_theory(const std::string& t);
void add_dispersion_options(CLI::App& sub, DispersionOptions& o);

}  // namespace granbench::cli

// `granbench dispersion --theory twod`: the exact 2D linear stability (linear_stability_2d.hpp)
// for each requested Lx, with its convergence check, every unstable branch, and the short-wave
// ill-posedness probe; JSON, table, and an HDF5 file with the three theories over k_hat.
#pragma once

#include <optional>
#include <vector>

#include "analysis/cli/cli_common.hpp"
#include "analysis/linear2d/light_layer.hpp"
#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"

namespace granbench::cli {

struct TwoDDispersionOptions {
  int N = 32;  // Chebyshev intervals; the check uses 3N/2
  std::string curve_name;
  double angle_deg = 0.0;
  std::optional<linear2d::LightLayer> light_layer;  // --light-layer
};

void run_twod_dispersion(const SteadyState& s, const MuCurve& curve, const std::vector<double>& Lx,
                         const TwoDDispersionOptions& t, const OutputOptions& out);

}  // namespace granbench::cli

// The uniform-layer paper cases (§5.2 decelerating, §6.2 high-speed) from a case file: one
// layer run (layer_run.hpp) per curve and resolution, the grid dependence between resolutions
// of each curve (grid_dependence.hpp), one HDF5 file and a JSON summary.
//
// Case-file keys (case_file.hpp; [smoke]/[paper] may override any of them):
//   curves = ["jop", "low-i"]    the run's mu(I) curves
//   initial_curve = "jop"         curve of the initial Bagnold state (default: each run's own)
//   angle0, angle                 slope of the initial state and of the run [deg]
//   h0, Lx_over_h0, Lz_over_h0    layer depth [m] and domain size in units of h0
//   nx, nz                        lists, one entry per resolution (coarse first)
//   t_end, samples                run length [s] and evenly spaced sample times
//   noise                         relative random noise on the initial velocity (default 0)
//   eta_max, eta_min, D_min, dt_max, cfl, mixing   solver settings (twod/parameters.hpp)
#pragma once

#include <atomic>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/cases/case_file.hpp"
#include "analysis/cases/grid_dependence.hpp"
#include "analysis/cases/layer_run.hpp"

namespace granbench::cases {

struct LayerCaseSpec {
  std::string name, title, resolution;
  std::vector<std::string> curves;
  double h0 = 4e-3;
  double angle0_deg = 24.0, angle_deg = 10.0;
  std::vector<LayerRunSpec> runs;  // curves x resolutions, coarse first within a curve
};

// Reads and validates the keys; throws CaseFileError naming the key.
LayerCaseSpec layer_case_spec(const CaseFile& file, const std::string& resolution);

struct LayerCaseResult {
  std::vector<LayerRunRecord> runs;
  std::vector<std::pair<std::string, GridDependence>> grid_dependence;  // per curve
  nlohmann::json summary;
};

// What the case tells its caller after every sample of any run: one status line (each run's label
// and simulated time) and the fraction of the work done, each run weighted by its cost
// (cells^(3/2): the cells times the steps, which grow with the finer spacing), for an ETA.
using LayerCaseProgress = std::function<void(const std::string& status, double fraction_done)>;

// Runs every layer run (up to `jobs` at once); a stop request ends them all at their next sample.
LayerCaseResult run_layer_case(const LayerCaseSpec& spec, unsigned jobs,
                               const std::atomic<bool>* stop,
                               const LayerCaseProgress& progress = {});

void write_layer_case(const std::string& path, const LayerCaseSpec& spec, const LayerCaseResult& r);

}  // namespace granbench::cases

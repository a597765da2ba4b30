// A 2D growth rate extrapolated to cells of no height: the seeded run again on half the cells
// across the layer, measured like the first, and the pair extrapolated with the deficit law's
// order (growth_deficit_law.hpp). Near the 2D cutoff a grid's deficit is a large part of a small
// growth rate; the extrapolation takes it out at the cost of a run on a quarter or so of the work
// (docs/twod-validation.md §3, "Extrapolated from half the cells across the layer").
#pragma once

#include <cmath>
#include <string>

#include "analysis/comparison/chute_case.hpp"
#include "analysis/comparison/growth_deficit_law.hpp"
#include "analysis/comparison/model_runs.hpp"
#include "analysis/comparison/twod_settings.hpp"

namespace granbench {

struct TwodExtrapolation {
  int nx = 0, nz = 0;                   // the second run's grid
  double growth_rate_half_cells = NAN;  // measured on it
  double dz_ratio = NAN;                // its cell height over the first run's
  ExtrapolatedGrowth growth{NAN, NAN, NAN};
  RunOutcome outcome = RunOutcome::Completed;  // of the second run
  double wall_seconds = 0.0;
  long steps = 0;
  std::string reason;  // why there is no extrapolation (empty when there is one)
  bool found() const { return reason.empty(); }
};

// The settings of the second run: `fine` with half its cells across the layer.
TwodSettings half_cells_across(const TwodSettings& fine);

// The half grid's cells per h0, and whether the deficit law holds there (at least
// kGrowthDeficitFewestCellsPerDepth): where it does not, no run is made.
double half_grid_cells_per_depth(const TwodSettings& fine, double h0);

// The extrapolation of `fine_growth`, the growth rate measured on run_twod(c, fine): runs c on
// half_cells_across(fine) and measures the wave nearest seeded_phase_speed.
TwodExtrapolation extrapolate_twod_growth(const ChuteCase& c, const TwodSettings& fine,
                                          double fine_growth, double seeded_phase_speed,
                                          const RunControl& ctl = {});

// The same in two steps, for a caller that runs the half grid beside the first run (compare):
// the run on half_cells_across(fine) and its measurement (no run where the half grid is below
// the law's range; fine.threads are the threads it takes); then, once the first run's growth
// is known, the extrapolation.
TwodExtrapolation run_half_grid(const ChuteCase& c, const TwodSettings& fine,
                                double seeded_phase_speed, const RunControl& ctl = {});
void extrapolate_from(TwodExtrapolation& half_run, double fine_growth);

}  // namespace granbench

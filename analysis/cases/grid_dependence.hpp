// How much two resolutions of the same uniform-layer run disagree (the grid-dependence figure of
// the decelerating case, §5.2): at every common sample time, the root-mean-square over the layer
// of log10(I_fine / I_coarse), with the fine profile restricted to the coarse cells (arithmetic
// mean of the fine cells each coarse cell covers). For a well-posed problem this falls as the
// grid is refined; for an ill-posed one it grows in time, because the fastest-growing
// perturbations sit at the grid scale, and refining does not make it go away.
//
// Only coarse cells lying wholly below h0 - dz_coarse count: the interface cell and the one
// under it carry the VOF surface, not the bulk rheology.
//
// Each sample also says whether both runs are still flowing: some bulk row's downslope-averaged
// speed above `flowing_speed`. The comparison means something only then. As a layer comes to
// rest its I falls by four decades (to the floor that D_min sets) within a few milliseconds, so
// in those samples the log difference measures how far apart in time the two grids stop, not
// how the rheology behaves on them (docs/paper-cases.md, decelerating).
#pragma once

#include <vector>

#include "analysis/cases/layer_run.hpp"

namespace granbench::cases {

// The number of cells k = 0 .. n-1 lying wholly below h0 - dz (the bulk of the layer).
int bulk_cells(int nz, double Lz, double h0);

struct GridDependence {
  std::vector<double> t;            // common sample times
  std::vector<double> rms_log10_I;  // [t] (NaN where either profile is missing)
  std::vector<bool> both_flowing;   // [t] both runs above flowing_speed (false without u_profile)
};

// The speed [m/s] below which a layer counts as at rest: the criterion of docs/paper-cases.md.
constexpr double default_flowing_speed = 1e-3;

// Whether some bulk row of `run` (cells wholly below h0 - dz) has |mean u| > flowing_speed at
// sample n.
bool is_flowing(const LayerRunRecord& run, std::size_t n, double h0, double flowing_speed);

// fine.nz must be an integer multiple of coarse.nz, on the same Lz; throws std::invalid_argument.
GridDependence grid_dependence(const LayerRunRecord& coarse, const LayerRunRecord& fine, double h0,
                               double flowing_speed = default_flowing_speed);

}  // namespace granbench::cases

// How much two resolutions of the same uniform-layer run disagree (the grid-dependence figure of
// the decelerating case, §5.2): at every common sample time, the root-mean-square over the layer
// of log10(I_fine / I_coarse), with the fine profile restricted to the coarse cells (arithmetic
// mean of the fine cells each coarse cell covers). For a well-posed problem this falls as the
// grid is refined; for an ill-posed one it grows in time, because the fastest-growing
// perturbations sit at the grid scale, and refining does not make it go away.
//
// Only coarse cells lying wholly below h0 - dz_coarse count: the interface cell and the one
// under it carry the VOF surface, not the bulk rheology.
#pragma once

#include <vector>

#include "analysis/cases/layer_run.hpp"

namespace granbench::cases {

// The number of cells k = 0 .. n-1 lying wholly below h0 - dz (the bulk of the layer).
int bulk_cells(int nz, double Lz, double h0);

struct GridDependence {
  std::vector<double> t;            // common sample times
  std::vector<double> rms_log10_I;  // [t] (NaN where either profile is missing)
};

// fine.nz must be an integer multiple of coarse.nz, on the same Lz; throws std::invalid_argument.
GridDependence grid_dependence(const LayerRunRecord& coarse, const LayerRunRecord& fine, double h0);

}  // namespace granbench::cases

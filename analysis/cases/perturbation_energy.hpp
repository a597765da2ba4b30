// The growth of x-dependent perturbations in a uniform-layer run (the high-speed case, §6.2,
// figure 8): is the flat layer unstable, and how fast do its perturbations grow on this grid?
//
// E(t) = the mean, over the cells of the rows at z <= 0.8 h0 that are grains all along x, of
// ((I - <I>_x) / <I>_x)^2, <I>_x the mean along x of that row. The rows next to the surface are
// left out: the VOF surface row feeds an x-variation of its own into them (1e-7 to 1e-3 of this
// measure) while the interior follows the rheology. In the linear regime I' is linear in the
// velocity perturbation, so E grows at the rate of the perturbation kinetic energy, twice the
// amplitude's rate (docs/paper-cases.md, high-speed: checked against the kinetic energy of u, w).
//
// Its growth rate: the least-squares slope of ln E over the exponential phase, the samples from
// the first with E >= `from` to the last before E exceeds `to` (a perturbation grown out of the
// noise, not yet saturated). For an ill-posed flow (Jop's curve at I above I2N) that rate keeps
// rising as the grid is refined, because the fastest-growing waves are the shortest the grid
// holds; for a well-posed one E never leaves the level of the noise.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/cases/layer_run.hpp"

namespace granbench::cases {

// E at each sample of `run` (NaN at a sample with no row that is grains all along x).
std::vector<double> perturbation_energy(const LayerRunRecord& run, double h0);

struct EnergyGrowth {
  std::optional<double> rate;  // d ln E / dt [1/s] over the window; empty: no exponential phase
  double t_from = 0.0, t_to = 0.0;
  int samples = 0;
  std::string reason;  // why there is no rate
};

// The growth rate of E over its exponential phase between the levels `from` and `to` (at least
// 4 samples in it).
EnergyGrowth energy_growth(const std::vector<double>& t, const std::vector<double>& E,
                           double from = 1e-8, double to = 1e-3);

}  // namespace granbench::cases

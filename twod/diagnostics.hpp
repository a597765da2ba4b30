// Diagnostics of a 2D state (diagnostics.cpp): the surface h(x), depth-averaged velocity,
// flux, granular volume, the range of I visited and the ill-posed fraction (3.9).
#pragma once

#include <vector>

#include "common/mu_curves.hpp"
#include "twod/fields.hpp"
#include "twod/grid.hpp"

namespace granbench::twod {

// h_i = sum_k f_ik dz (column integral of the volume fraction).
std::vector<double> surface_heights(const Grid& g, const std::vector<double>& f);
// u_bar_i = (sum_k f u dz) / h_i with u averaged to cell centres (0 where h_i = 0), in the lab
// frame (u + Grid::frame_speed); column i of the grid, wherever it is in the lab (frame.hpp).
std::vector<double> depth_averaged_velocity(const Grid& g, const Fields& s);
// Mean over x of the granular flux  int f u dz  [m^2/s], in the lab frame.
double mean_flux(const Grid& g, const Fields& s);
double granular_volume(const Grid& g, const std::vector<double>& f);  // sum f V [m^2]
double max_speed(const Fields& s);

struct RheologyStats {
  double I_min = 0.0, I_max = 0.0;  // over cells with f >= 1/2 and p > 0
  double illposed_fraction = 0.0;   // granular volume with C(I) > 0 / granular volume
};
RheologyStats rheology_stats(const Grid& g, const std::vector<double>& f,
                             const std::vector<double>& I, const MuCurve& curve);
// C(I) (3.9) per cell (NaN where I is not finite).
std::vector<double> ill_posedness_field(const std::vector<double>& I, const MuCurve& curve);

}  // namespace granbench::twod

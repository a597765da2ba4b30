// The paper's growth-rate estimator (7.12) from a SurfaceSeries:
//
//   lambda = 1/(max(h) - h0) d/dt (max(h) - h0),                                   (7.12)
//
// averaged over a time window [t_a, t_b] where growth is linear (the paper uses 0.5 s < t < 3 s
// in figure 12). The time average of d/dt ln(max(h) - h0) is the difference quotient of the
// logarithm between the window's ends; the least-squares slope over the window is given as well.
#pragma once

#include "analysis/spectral/spectral_growth.hpp"
#include "common/surface_series.hpp"

namespace granbench {

struct Estimate712 {
  double growth_rate = 0.0;  // window average of (7.12) [1/s]
  LinearFit fit;             // least-squares slope of ln(max h - h0) over the same samples
};

// max_j h(x_j, t_n) - h0 for each sample (h0 = s.h0, the steady uniform depth).
std::vector<double> excess_height(const SurfaceSeries& s);
// Throws std::invalid_argument if the window holds fewer than two samples or max h <= h0 there.
Estimate712 growth_estimate_712(const SurfaceSeries& s, double t_a, double t_b);

}  // namespace granbench

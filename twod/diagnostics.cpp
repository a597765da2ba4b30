// Diagnostics of the 2D flow: column integrals of the volume fraction (the SurfaceSeries both
// models share), flux, and the well-posedness condition (3.9) over the granular cells,
//   C = 4 (I mu'/mu)^2 - 4 (I mu'/mu) + mu^2 (1 - I mu'/(2 mu))^2,  ill posed where C > 0.
#include "twod/diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/ill_posedness.hpp"
#include "twod/parallel.hpp"

namespace granbench::twod {

std::vector<double> surface_heights(const Grid& g, const std::vector<double>& f) {
  std::vector<double> h(g.nx, 0.0);
  // columns in parallel; each column's sum runs over k in the same order as on one thread
  parallel_for(g.nx, true, [&](int i) {
    for (int k = 0; k < g.nz; ++k) h[i] += f[g.at(i, k)] * g.dz;
  });
  return h;
}

std::vector<double> depth_averaged_velocity(const Grid& g, const Fields& s) {
  std::vector<double> q(g.nx, 0.0);
  const auto h = surface_heights(g, s.f);
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const double uc = 0.5 * (s.u[g.at(i, k)] + s.u[g.at(i + 1, k)]);
      q[i] += s.f[g.at(i, k)] * uc * g.dz;
    }
  // in the lab frame: the grid moves at frame_speed (grid.hpp)
  for (int i = 0; i < g.nx; ++i) q[i] = h[i] > 0.0 ? q[i] / h[i] + g.frame_speed : 0.0;
  return q;
}

double mean_flux(const Grid& g, const Fields& s) {
  const auto h = surface_heights(g, s.f);
  const auto ub = depth_averaged_velocity(g, s);
  double q = 0.0;
  for (int i = 0; i < g.nx; ++i) q += h[i] * ub[i];
  return q / g.nx;
}

double granular_volume(const Grid& g, const std::vector<double>& f) {
  double sum = 0.0;
  for (double v : f) sum += v;
  return sum * g.cell_volume();
}

double max_speed(const Fields& s) {
  double m = 0.0;
  for (double v : s.u) m = std::max(m, std::abs(v));
  for (double v : s.w) m = std::max(m, std::abs(v));
  return m;
}

std::vector<double> ill_posedness_field(const std::vector<double>& I, const MuCurve& curve) {
  std::vector<double> C(I.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t n = 0; n < I.size(); ++n)
    if (std::isfinite(I[n]) && I[n] > 0.0)
      C[n] = ill_posedness_C(curve.mu(I[n]), I[n] * curve.dmu_dI(I[n]));  // (3.9)
  return C;
}

RheologyStats rheology_stats(const Grid& g, const std::vector<double>& f,
                             const std::vector<double>& I, const MuCurve& curve) {
  RheologyStats r;
  r.I_min = std::numeric_limits<double>::infinity();
  r.I_max = 0.0;
  double vol = 0.0, ill = 0.0;
  for (std::size_t n = 0; n < g.cells(); ++n) {
    if (f[n] <= 0.0) continue;
    vol += f[n];
    if (!std::isfinite(I[n]) || I[n] <= 0.0) continue;
    if (f[n] >= 0.5) {
      r.I_min = std::min(r.I_min, I[n]);
      r.I_max = std::max(r.I_max, I[n]);
    }
    if (ill_posedness_C(curve.mu(I[n]), I[n] * curve.dmu_dI(I[n])) > 0.0) ill += f[n];  // (3.9)
  }
  if (!(r.I_max > 0.0)) r.I_min = r.I_max = std::numeric_limits<double>::quiet_NaN();
  r.illposed_fraction = vol > 0.0 ? ill / vol : 0.0;
  return r;
}

}  // namespace granbench::twod

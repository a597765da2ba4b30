// Difference of the downslope-averaged I between two resolutions (grid_dependence.hpp).
#include "analysis/cases/grid_dependence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace granbench::cases {

int bulk_cells(int nz, double Lz, double h0) {
  const double dz = Lz / nz;
  return std::clamp(int(std::floor((h0 - dz) / dz + 1e-9)), 0, nz);
}

bool is_flowing(const LayerRunRecord& run, std::size_t n, double h0, double flowing_speed) {
  if (n >= run.u_profile.size()) return false;
  const int bulk = bulk_cells(run.nz, run.Lz, h0);
  for (int k = 0; k < bulk; ++k)
    if (std::abs(run.u_profile[n][k]) > flowing_speed) return true;
  return false;
}

GridDependence grid_dependence(const LayerRunRecord& coarse, const LayerRunRecord& fine, double h0,
                               double flowing_speed) {
  if (coarse.nz <= 0 || fine.nz % coarse.nz != 0 ||
      std::abs(fine.Lz - coarse.Lz) > 1e-12 * coarse.Lz)
    throw std::invalid_argument("grid_dependence: the fine grid must refine the coarse one in z");
  const int ratio = fine.nz / coarse.nz;
  const int bulk = bulk_cells(coarse.nz, coarse.Lz, h0);
  GridDependence out;
  const std::size_t nt = std::min(coarse.t.size(), fine.t.size());
  for (std::size_t n = 0; n < nt; ++n) {
    double sum = 0.0;
    int count = 0;
    for (int k = 0; k < bulk; ++k) {
      double fine_mean = 0.0;
      for (int q = 0; q < ratio; ++q) fine_mean += fine.I_profile[n][ratio * k + q] / ratio;
      const double c = coarse.I_profile[n][k];
      if (!(fine_mean > 0.0) || !(c > 0.0)) continue;  // NaN or I = 0: no log difference
      const double d = std::log10(fine_mean / c);
      sum += d * d;
      ++count;
    }
    out.t.push_back(coarse.t[n]);
    out.rms_log10_I.push_back(count > 0 ? std::sqrt(sum / count)
                                        : std::numeric_limits<double>::quiet_NaN());
    out.both_flowing.push_back(is_flowing(coarse, n, h0, flowing_speed) &&
                               is_flowing(fine, n, h0, flowing_speed));
  }
  return out;
}

}  // namespace granbench::cases

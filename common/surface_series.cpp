// SurfaceSeries storage; see surface_series.hpp.
#include "common/surface_series.hpp"

#include <stdexcept>

namespace granbench {

SurfaceSeries SurfaceSeries::uniform_grid(double Lx, std::size_t nx, double h0) {
  SurfaceSeries s;
  s.Lx = Lx;
  s.h0 = h0;
  s.x.resize(nx);
  const double dx = Lx / static_cast<double>(nx);
  for (std::size_t i = 0; i < nx; ++i) s.x[i] = (static_cast<double>(i) + 0.5) * dx;
  return s;
}

void SurfaceSeries::append(double time, std::span<const double> heights,
                           std::span<const double> u) {
  if (heights.size() != nx()) throw std::invalid_argument("SurfaceSeries: wrong number of heights");
  if (!u.empty() && u.size() != nx())
    throw std::invalid_argument("SurfaceSeries: wrong number of velocities");
  if (!u.empty() != !u_mean.empty() && !t.empty())
    throw std::invalid_argument("SurfaceSeries: velocities given for some samples only");
  t.push_back(time);
  h.insert(h.end(), heights.begin(), heights.end());
  u_mean.insert(u_mean.end(), u.begin(), u.end());
}

}  // namespace granbench

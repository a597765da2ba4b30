// SurfaceSeries: the free-surface height h(x_i, t_n) of a periodic chute flow, sampled at a fixed
// interval. Both models produce it (depthavg directly, twod as the column integral of the
// volume fraction), so every analysis in granbench works on either.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace granbench {

struct SurfaceSeries {
  double Lx = 0.0;             // domain length [m]
  double h0 = 0.0;             // mean (base-state) depth [m]
  std::vector<double> x;       // cell-centre positions [m], size nx
  std::vector<double> t;       // sample times [s], size nt
  std::vector<double> h;       // heights [m], row-major [nt][nx]
  std::vector<double> u_mean;  // depth-averaged velocity [m/s], same shape as h, or empty

  static SurfaceSeries uniform_grid(double Lx, std::size_t nx, double h0);
  std::size_t nx() const { return x.size(); }
  std::size_t nt() const { return t.size(); }
  void append(double time, std::span<const double> heights, std::span<const double> u = {});
  std::span<const double> h_at(std::size_t n) const { return {h.data() + n * nx(), nx()}; }
  std::span<const double> u_at(std::size_t n) const { return {u_mean.data() + n * nx(), nx()}; }
};

}  // namespace granbench

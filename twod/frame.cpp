// The co-moving frame's conversions to the lab frame; see frame.hpp.
#include "twod/frame.hpp"

#include <cmath>

namespace granbench::twod {

double frame_offset(const Grid& g, double t) {
  const double s = std::fmod(g.frame_speed * t, g.Lx);
  return s < 0.0 ? s + g.Lx : s;
}

double lab_position(const Grid& g, double x, double t) {
  const double y = std::fmod(x + frame_offset(g, t), g.Lx);
  return y < 0.0 ? y + g.Lx : y;
}

std::vector<double> columns_in_lab_frame(const Grid& g, double t, const std::vector<double>& v) {
  if (g.frame_speed == 0.0) return v;
  // lab(x_i) = grid(x_i - s): grid column index i - s/dx = i - n - theta, theta in [0, 1)
  const double cells = frame_offset(g, t) / g.dx;
  const int n = static_cast<int>(std::floor(cells));
  const double theta = cells - n;  // at theta = 0 the weights are (0, 0, 1, 0): a permutation
  // Cubic Lagrange weights on the nodes 0, 1, 2, 3 = columns j-2 .. j+1 (j = i - n) at node
  // position 2 - theta, i.e. p = 1 - theta past node 1, between nodes 1 and 2.
  const double p = 1.0 - theta;
  const double w0 = -p * (p - 1.0) * (p - 2.0) / 6.0, w1 = (p + 1.0) * (p - 1.0) * (p - 2.0) / 2.0,
               w2 = -(p + 1.0) * p * (p - 2.0) / 2.0, w3 = (p + 1.0) * p * (p - 1.0) / 6.0;
  std::vector<double> out(v.size());
  auto at = [&](int j) { return v[((j % g.nx) + g.nx) % g.nx]; };
  for (int i = 0; i < g.nx; ++i) {
    const int j = i - n;
    out[i] = w0 * at(j - 2) + w1 * at(j - 1) + w2 * at(j) + w3 * at(j + 1);
  }
  return out;
}

ColumnShift lab_column_shift(const Grid& g, double t) {
  const double cells = frame_offset(g, t) / g.dx;
  ColumnShift c;
  c.shift = static_cast<int>(std::lround(cells));
  c.remainder = (cells - c.shift) * g.dx;
  c.shift %= g.nx;
  return c;
}

}  // namespace granbench::twod

// Chebyshev Gauss-Lobatto nodes, differentiation matrix and barycentric weights on s in [0, 1].
// The off-diagonal entries are D_ij = (c_i/c_j) (-1)^(i+j) / (x_i - x_j) on x in [-1, 1]
// (c_0 = c_N = 2, else 1); the diagonal is minus the row sum ("negative sum trick"), which keeps
// D applied to a constant exactly zero. s = (1 + x)/2 doubles every entry.
#include "analysis/linear2d/chebyshev.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace granbench::linear2d {

ChebyshevGrid::ChebyshevGrid(int N) : N_(N) {
  if (N < 2) throw std::invalid_argument("Chebyshev grid needs N >= 2 intervals");
  const int n = N + 1;
  Eigen::VectorXd x(n), c(n);
  s_.resize(n);
  weight_.resize(n);
  for (int j = 0; j < n; ++j) {
    x(j) = std::cos(std::numbers::pi * j / N);
    s_(j) = 0.5 * (1.0 + x(j));
    const double sign = (j % 2 == 0) ? 1.0 : -1.0;
    const double end = (j == 0 || j == N) ? 2.0 : 1.0;
    c(j) = end * sign;
    weight_(j) = sign / end;
  }
  D_ = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    double row = 0.0;
    for (int j = 0; j < n; ++j) {
      if (i == j) continue;
      D_(i, j) = 2.0 * (c(i) / c(j)) / (x(i) - x(j));  // factor 2: d/ds = 2 d/dx
      row += D_(i, j);
    }
    D_(i, i) = -row;
  }
}

}  // namespace granbench::linear2d

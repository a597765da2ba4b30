// Chebyshev collocation on s in [0, 1] for the 2D linear stability of the Bagnold flow
// (docs/linear-theory.md, "Discretisation").
//
// Gauss-Lobatto nodes s_j = (1 + cos(pi j/N))/2, j = 0..N (s_0 = 1, s_N = 0), the first-derivative
// matrix D with (D f)_j = f'(s_j) for polynomials of degree <= N (Trefethen, "Spectral Methods in
// MATLAB", ch. 6, rescaled from [-1, 1] to [0, 1]), and barycentric interpolation of nodal values
// to any s (Berrut & Trefethen 2004), used to evaluate eigenfunctions off the grid.
#pragma once

#include <Eigen/Dense>

namespace granbench::linear2d {

class ChebyshevGrid {
 public:
  explicit ChebyshevGrid(int N);  // N >= 2 intervals, N + 1 nodes

  int intervals() const { return N_; }
  int nodes() const { return N_ + 1; }
  const Eigen::VectorXd& s() const { return s_; }
  const Eigen::MatrixXd& D() const { return D_; }  // d/ds on [0, 1]

  // Polynomial interpolant of the nodal values f (size N + 1) at s in [0, 1].
  template <typename Vec>
  typename Vec::Scalar interpolate(const Vec& f, double s) const {
    using Scalar = typename Vec::Scalar;
    Scalar num(0);
    double den = 0.0;
    for (int j = 0; j <= N_; ++j) {
      const double ds = s - s_(j);
      if (ds == 0.0) return f(j);
      const double w = weight_(j) / ds;
      num += w * f(j);
      den += w;
    }
    return num / den;
  }

 private:
  int N_;
  Eigen::VectorXd s_;
  Eigen::VectorXd weight_;  // barycentric weights (-1)^j, halved at the ends
  Eigen::MatrixXd D_;
};

}  // namespace granbench::linear2d

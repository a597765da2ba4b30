// Assembly of the collocation matrices of the 2D linear stability problem; the equations are
// documented in analysis/linear2d/operator.hpp. Each first-order equation is collocated at all N +
// 1 nodes; one row of each is replaced by its boundary condition (row replacement), u and w at the
// bed, T and N at the surface. The kinematic condition is the last row.
#include "analysis/linear2d/operator.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

namespace granbench::linear2d {

namespace {
int map_power(VerticalMap map) {
  return map == VerticalMap::SquareRoot ? 2 : 1;
}
}  // namespace

double map_height(VerticalMap map, double s) {
  return 1.0 - std::pow(s, map_power(map));
}

double map_coordinate(VerticalMap map, double z) {
  const double depth = std::max(0.0, 1.0 - z);
  return map == VerticalMap::SquareRoot ? std::sqrt(depth) : depth;
}

Pencil assemble_pencil(const LinearBaseState& b, double k_hat, const ChebyshevGrid& grid,
                       VerticalMap map, const SurfaceLayerScaling& layer) {
  using cd = std::complex<double>;
  const int m = map_power(map);
  // eta_s / z_s ~ s^(m beta - m + 1) must stay bounded at the surface s = 0.
  const double a_power = m * b.beta - m + 1.0;
  if (a_power < 0.0)
    throw std::invalid_argument(
        "the z = 1 - s^2 map needs a viscosity vanishing like sqrt(1 - z); use the linear map");
  // With an overburden delta the viscosity is ~ sqrt(1 - z + delta): the map becomes
  // z = 1 + delta - s^2 on s in [sqrt(delta), sqrt(1 + delta)], taken linearly onto the grid's
  // [0, 1] (s = s_top + ell sigma). delta = 0 gives s = sigma, the map above, bit for bit.
  const double delta = b.overburden;
  if (delta < 0.0 || (delta > 0.0 && (map != VerticalMap::SquareRoot || b.beta != 0.5)))
    throw std::invalid_argument("an overburden needs the Bagnold state and the square-root map");
  const double s_top = std::sqrt(delta), ell = std::sqrt(1.0 + delta) - s_top;

  const int N = grid.intervals();
  const int n = N + 1;
  Pencil P;
  P.N = N;
  P.map = map;
  const int dim = 4 * n + 1;
  P.A = Eigen::MatrixXcd::Zero(dim, dim);
  P.B = Eigen::MatrixXcd::Zero(dim, dim);
  const Eigen::MatrixXd& D = grid.D();
  const cd ik(0.0, k_hat);
  const double k2 = k_hat * k_hat;
  const double F2 = b.F * b.F;
  const int iu = P.u(), iw = P.w(), iN = P.normal(), iT = P.shear(), iH = P.h();

  for (int j = 0; j < n; ++j) {
    const double s = s_top + ell * grid.s()(j);
    const double z = map_height(map, s) + delta;
    const double zs = -m * std::pow(s, m - 1) * ell;   // dz/dsigma
    const double depth_pow = std::pow(s, m * b.beta);  // (1 - z + delta)^beta
    const bool in_layer = 1.0 - z < layer.depth;
    const double fn = in_layer ? layer.eta_n : 1.0, fs = in_layer ? layer.eta_s : 1.0;
    const double q = in_layer ? layer.q * b.q : b.q;
    const double eta_n = fn * b.eta_n0 * depth_pow;
    const double eta_s = fs * b.eta_s0 * depth_pow;
    const double a = -fs * (b.eta_s0 / (m * ell)) * std::pow(s, a_power);  // eta_s / z_s
    const double U0 = b.U0(z), dU0 = b.dU0(z);

    // Constitutive law tau_xz = eta_s (du/dz + i k w) + q p, p = N - 2 i k eta_n u  (3.2)-(3.3)
    P.A.block(iu + j, iu, 1, n) = (-a * D.row(j)).cast<cd>();
    P.A(iu + j, iu + j) += 2.0 * q * eta_n * ik;
    P.A(iu + j, iw + j) = -eta_s * ik;
    P.A(iu + j, iN + j) = -q;
    P.A(iu + j, iT + j) = 1.0;
    // Mass (2.9): i k u + dw/dz = 0
    P.A.block(iw + j, iw, 1, n) = D.row(j).cast<cd>();
    P.A(iw + j, iu + j) = zs * ik;
    // x momentum (2.10)
    P.A.block(iT + j, iT, 1, n) = D.row(j).cast<cd>();
    P.A(iT + j, iu + j) = -zs * (F2 * ik * U0 + 4.0 * eta_n * k2);
    P.A(iT + j, iw + j) = -zs * F2 * dU0;
    P.A(iT + j, iN + j) = -zs * ik;
    P.B(iT + j, iu + j) = zs * F2;
    // z momentum (2.10)
    P.A.block(iN + j, iN, 1, n) = D.row(j).cast<cd>();
    P.A(iN + j, iT + j) = -zs * ik;
    P.A(iN + j, iw + j) = zs * F2 * ik * U0;
    P.B(iN + j, iw + j) = -zs * F2;
  }

  auto replace_row = [&](int row) {
    P.A.row(row).setZero();
    P.B.row(row).setZero();
  };
  const int bed = 0, surface = N;
  replace_row(iu + bed);  // no slip
  P.A(iu + bed, iu + bed) = 1.0;
  replace_row(iw + bed);  // no penetration
  P.A(iw + bed, iw + bed) = 1.0;
  replace_row(iT + surface);  // tangential stress at z = 1 + h: tau_xz - mu h = 0
  P.A(iT + surface, iT + surface) = 1.0;
  P.A(iT + surface, iH) = -b.mu;
  replace_row(iN + surface);  // normal stress at z = 1 + h: p - tau_zz = h
  P.A(iN + surface, iN + surface) = 1.0;
  P.A(iN + surface, iH) = -1.0;
  // Kinematic condition: (lambda + i k U0(1)) h = w(1)
  P.A(iH, iH) = -ik * b.U_surface();
  P.A(iH, iw + surface) = 1.0;
  P.B(iH, iH) = 1.0;
  return P;
}

}  // namespace granbench::linear2d

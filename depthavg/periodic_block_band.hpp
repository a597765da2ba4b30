// The Newton matrix of the depth-averaged integrator, A = I - gamma J, stored and solved as what it
// is: periodic block-banded, with one 2x2 block per pair of cells (rows h_i, q_i; columns h_j,
// q_j) at cyclic distance <= r, r the stencil radius of the right-hand side (2: rhs.hpp).
//
// Solve: A = B + E, where B holds the blocks with |i - j| <= r (a plain block band) and E the
// periodic wrap-around blocks, which couple the first r cells with the last r. E has 4r non-zero
// scalar rows, so the Sherman-Morrison-Woodbury identity gives A exactly from B:
//
//   A^{-1} b = y - Z S^{-1} (V^T y),   y = B^{-1} b,   Z = B^{-1} U,   S = I + V^T Z,
//
// with E = U V^T, U selecting the 4r wrap rows and V^T their wrap entries. B is factored by block
// LU without pivoting (each 2x2 pivot block inverted exactly, no row exchanged): the fill-in stays
// inside the band and the solve is a short fixed loop per cell (forward r block products,
// backward r + 1). The set-up solves B for the 4r columns of U and factors the small S (Eigen,
// partial pivoting); a solve then costs one band solve and 4r dot products and updates of length
// 2 nx. For I - gamma J of a well-posed, dissipative semi-discretisation the pivot blocks and S
// stay well away from singular; a (nearly) singular one is reported, and CVODE then retries with
// a fresh Jacobian or a smaller step.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace granbench::depthavg {

class PeriodicBlockBandMatrix {
 public:
  using Block = std::array<double, 4>;  // row-major 2x2: (a, b) at 2 a + b

  // Requires cells >= 2 radius + 1, so that the 2 radius + 1 blocks of a row are distinct cells.
  PeriodicBlockBandMatrix(std::size_t cells, std::size_t radius);
  std::size_t cells() const { return cells_; }
  std::size_t radius() const { return radius_; }
  void set_zero();
  // The block of cell row i and cell column j; requires cyclic distance |i - j| <= radius.
  Block& block(std::size_t i, std::size_t j) { return blocks_[index(i, j)]; }
  const Block& block(std::size_t i, std::size_t j) const { return blocks_[index(i, j)]; }

  // In place: this = I - gamma J (J of the same shape), then its factorisation (see above). False
  // when a pivot block or S is (nearly) singular; the matrix is then unusable until the next call.
  bool factor_shifted(const PeriodicBlockBandMatrix& J, double gamma);
  // x = A^{-1} x with the factors of factor_shifted; x interleaved (h_0, q_0, h_1, q_1, ...).
  void solve(std::span<double> x) const;

 private:
  std::size_t index(std::size_t i, std::size_t j) const;
  bool wraps(std::size_t i, std::size_t j) const;  // a block of E rather than of B
  void band_solve(std::span<double> x) const;      // x = B^{-1} x
  double wrap_row_dot(std::size_t row, std::span<const double> x) const;  // (V^T x)_row

  std::size_t cells_, radius_;
  std::vector<Block> blocks_;           // B's factors (after factor_shifted) and E's blocks
  std::vector<std::size_t> wrap_rows_;  // the scalar rows of E, 4r of them
  std::vector<double> Z_;               // B^{-1} U, column k at [k * 2 cells, (k + 1) * 2 cells)
  Eigen::PartialPivLU<Eigen::MatrixXd> S_;
  mutable Eigen::VectorXd wrap_values_, correction_;  // scratch of solve: V^T y and S^{-1} V^T y
};

}  // namespace granbench::depthavg

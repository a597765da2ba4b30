// The preconditioner matrix of the depth-averaged integrator, P = I - gamma J, stored and solved
// as what it is: block-banded, with one 2x2 block per pair of cells (rows h_i, q_i; columns
// h_j, q_j) and |i - j| <= r, r the stencil radius of the right-hand side (2: rhs.hpp).
//
// The periodic wrap-around entries are lumped onto the diagonal block by the caller
// (cvode_integrator.hpp), so the matrix is block (2r+1)-diagonal. It is factored by block LU
// without pivoting: each 2x2 pivot block is inverted exactly, and no row is exchanged. Compared
// with a general band LU with partial pivoting over the 2(2r+1) - 1 scalar diagonals (SUNDIALS'
// band solver, used before), that keeps the fill-in inside the band and makes the solve a short
// fixed loop per cell: forward, r block products; backward, r + 1. For P = I - gamma J of a
// well-posed, dissipative semi-discretisation the pivot blocks stay well away from singular; a
// (nearly) singular one is reported, and CVODE then retries with a fresh Jacobian or a smaller
// step.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace granbench::depthavg {

class BlockBandMatrix {
 public:
  using Block = std::array<double, 4>;  // row-major 2x2: (a, b) at 2 a + b

  BlockBandMatrix(std::size_t cells, std::size_t radius);
  std::size_t cells() const { return cells_; }
  std::size_t radius() const { return radius_; }
  void set_zero();
  // The block of cell row i and cell column j; requires |i - j| <= radius.
  Block& block(std::size_t i, std::size_t j) { return blocks_[index(i, j)]; }
  const Block& block(std::size_t i, std::size_t j) const { return blocks_[index(i, j)]; }

  // In place: this = I - gamma J (J of the same shape), then its block LU. False when a pivot
  // block is (nearly) singular; the matrix is then unusable until the next factorisation.
  bool factor_shifted(const BlockBandMatrix& J, double gamma);
  // x = P^{-1} x with the factors of factor_shifted; x interleaved (h_0, q_0, h_1, q_1, ...).
  void solve(std::span<double> x) const;

 private:
  std::size_t index(std::size_t i, std::size_t j) const {
    return i * (2 * radius_ + 1) + (j + radius_ - i);
  }
  std::size_t cells_, radius_;
  std::vector<Block> blocks_;
};

}  // namespace granbench::depthavg

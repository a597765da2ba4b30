// Block LU without pivoting of a block-banded matrix of 2x2 blocks; see block_band.hpp.
#include "depthavg/block_band.hpp"

#include <algorithm>
#include <cmath>

namespace granbench::depthavg {

namespace {

using Block = BlockBandMatrix::Block;

Block product(const Block& a, const Block& b) {
  return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2],
          a[2] * b[1] + a[3] * b[3]};
}

// The inverse of a, or false when a is singular to working precision (relative to its size).
bool invert(Block& a) {
  const double det = a[0] * a[3] - a[1] * a[2];
  const double size =
      std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2]), std::fabs(a[3])});
  if (!(std::fabs(det) > 1e-13 * size * size)) return false;  // also catches NaN
  const double s = 1.0 / det;
  a = {s * a[3], -s * a[1], -s * a[2], s * a[0]};
  return true;
}

}  // namespace

BlockBandMatrix::BlockBandMatrix(std::size_t cells, std::size_t radius)
    : cells_(cells), radius_(radius), blocks_(cells * (2 * radius + 1)) {}

void BlockBandMatrix::set_zero() {
  std::fill(blocks_.begin(), blocks_.end(), Block{});
}

bool BlockBandMatrix::factor_shifted(const BlockBandMatrix& J, double gamma) {
  const std::size_t n = cells_, r = radius_;
  for (std::size_t k = 0; k < blocks_.size(); ++k)
    for (int e = 0; e < 4; ++e) blocks_[k][e] = -gamma * J.blocks_[k][e];
  for (std::size_t i = 0; i < n; ++i) {
    block(i, i)[0] += 1.0;
    block(i, i)[3] += 1.0;
  }
  // Row k eliminates column k from rows k+1 .. k+r; the diagonal block is replaced by its inverse
  // and L_ik = A_ik A_kk^{-1} is stored where A_ik was.
  for (std::size_t k = 0; k < n; ++k) {
    if (!invert(block(k, k))) return false;
    const std::size_t last = std::min(n - 1, k + r);
    for (std::size_t i = k + 1; i <= last; ++i) {
      const Block L = product(block(i, k), block(k, k));
      block(i, k) = L;
      for (std::size_t j = k + 1; j <= last; ++j) {
        const Block LU = product(L, block(k, j));
        Block& a = block(i, j);
        for (int e = 0; e < 4; ++e) a[e] -= LU[e];
      }
    }
  }
  return true;
}

void BlockBandMatrix::solve(std::span<double> x) const {
  const std::size_t n = cells_, r = radius_;
  // Forward: y_i = b_i - sum_k L_ik y_k, k = i-r .. i-1.
  for (std::size_t i = 1; i < n; ++i) {
    double a = x[2 * i], b = x[2 * i + 1];
    for (std::size_t k = i > r ? i - r : 0; k < i; ++k) {
      const Block& L = block(i, k);
      a -= L[0] * x[2 * k] + L[1] * x[2 * k + 1];
      b -= L[2] * x[2 * k] + L[3] * x[2 * k + 1];
    }
    x[2 * i] = a;
    x[2 * i + 1] = b;
  }
  // Backward: x_i = A_ii^{-1} (y_i - sum_j U_ij x_j), j = i+1 .. i+r.
  for (std::size_t i = n; i-- > 0;) {
    double a = x[2 * i], b = x[2 * i + 1];
    for (std::size_t j = i + 1; j <= std::min(n - 1, i + r); ++j) {
      const Block& U = block(i, j);
      a -= U[0] * x[2 * j] + U[1] * x[2 * j + 1];
      b -= U[2] * x[2 * j] + U[3] * x[2 * j + 1];
    }
    const Block& D = block(i, i);
    x[2 * i] = D[0] * a + D[1] * b;
    x[2 * i + 1] = D[2] * a + D[3] * b;
  }
}

}  // namespace granbench::depthavg

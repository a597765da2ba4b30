// Block LU of the band part and a Woodbury correction for the periodic wrap-around; see
// periodic_block_band.hpp.
#include "depthavg/periodic_block_band.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granbench::depthavg {

namespace {

using Block = PeriodicBlockBandMatrix::Block;

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

PeriodicBlockBandMatrix::PeriodicBlockBandMatrix(std::size_t cells, std::size_t radius)
    : cells_(cells), radius_(radius), blocks_(cells * (2 * radius + 1)) {
  if (cells < 2 * radius + 1)
    throw std::invalid_argument("PeriodicBlockBandMatrix: fewer cells than the stencil width");
  // The cell rows with wrap-around blocks: the first r and the last r (distinct, as n > 2r).
  for (std::size_t c = 0; c < radius; ++c)
    for (std::size_t comp = 0; comp < 2; ++comp) wrap_rows_.push_back(2 * c + comp);
  for (std::size_t c = cells - radius; c < cells; ++c)
    for (std::size_t comp = 0; comp < 2; ++comp) wrap_rows_.push_back(2 * c + comp);
  Z_.resize(wrap_rows_.size() * 2 * cells);
  wrap_values_.resize(static_cast<Eigen::Index>(wrap_rows_.size()));
  correction_.resize(static_cast<Eigen::Index>(wrap_rows_.size()));
}

std::size_t PeriodicBlockBandMatrix::index(std::size_t i, std::size_t j) const {
  const std::size_t n = cells_, r = radius_;
  const std::size_t ahead = (j + n - i) % n;  // cyclic offset of j from i, in [0, n)
  const std::size_t slot = ahead <= r ? r + ahead : r + ahead - n;  // r + signed offset
  return i * (2 * r + 1) + slot;
}

bool PeriodicBlockBandMatrix::wraps(std::size_t i, std::size_t j) const {
  return (i > j ? i - j : j - i) > radius_;
}

void PeriodicBlockBandMatrix::set_zero() {
  std::fill(blocks_.begin(), blocks_.end(), Block{});
}

double PeriodicBlockBandMatrix::wrap_row_dot(std::size_t row, std::span<const double> x) const {
  const std::size_t n = cells_, r = radius_, i = row / 2, comp = row % 2;
  double sum = 0.0;
  for (std::size_t k = 0; k <= 2 * r; ++k) {
    const std::size_t j = (i + n + k - r) % n;
    if (!wraps(i, j)) continue;
    const Block& e = block(i, j);
    sum += e[2 * comp] * x[2 * j] + e[2 * comp + 1] * x[2 * j + 1];
  }
  return sum;
}

bool PeriodicBlockBandMatrix::factor_shifted(const PeriodicBlockBandMatrix& J, double gamma) {
  const std::size_t n = cells_, r = radius_;
  for (std::size_t k = 0; k < blocks_.size(); ++k)
    for (int e = 0; e < 4; ++e) blocks_[k][e] = -gamma * J.blocks_[k][e];
  for (std::size_t i = 0; i < n; ++i) {
    block(i, i)[0] += 1.0;
    block(i, i)[3] += 1.0;
  }
  // B: row k eliminates column k from rows k+1 .. k+r; the diagonal block is replaced by its
  // inverse and L_ik = A_ik A_kk^{-1} is stored where A_ik was. The wrap blocks are not touched.
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
  // Woodbury: Z = B^{-1} U, S = I + V^T Z.
  const std::size_t m = wrap_rows_.size(), len = 2 * n;
  Eigen::MatrixXd S =
      Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
  for (std::size_t k = 0; k < m; ++k) {
    std::span<double> z(Z_.data() + k * len, len);
    std::fill(z.begin(), z.end(), 0.0);
    z[wrap_rows_[k]] = 1.0;
    band_solve(z);
    for (std::size_t a = 0; a < m; ++a)
      S(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(k)) +=
          wrap_row_dot(wrap_rows_[a], z);
  }
  S_.compute(S);
  return S_.rcond() > 1e-13;  // false also for NaN
}

void PeriodicBlockBandMatrix::band_solve(std::span<double> x) const {
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

void PeriodicBlockBandMatrix::solve(std::span<double> x) const {
  const std::size_t m = wrap_rows_.size(), len = 2 * cells_;
  band_solve(x);
  for (std::size_t a = 0; a < m; ++a)
    wrap_values_(static_cast<Eigen::Index>(a)) = wrap_row_dot(wrap_rows_[a], x);
  correction_.noalias() = S_.solve(wrap_values_);
  for (std::size_t k = 0; k < m; ++k) {
    const double wk = correction_(static_cast<Eigen::Index>(k));
    const double* z = Z_.data() + k * len;
    for (std::size_t i = 0; i < len; ++i) x[i] -= wk * z[i];
  }
}

}  // namespace granbench::depthavg

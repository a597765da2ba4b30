// Symmetric block (line) Gauss-Seidel as a conjugate-gradient preconditioner for the viscous
// system (viscous_step.cpp). The unknowns of each grid column (u's, and separately w's) form a
// line; the couplings along the line - the stiff ones, since dz < dx and the viscosity jumps at
// the free surface across the columns - are solved exactly with the Thomas algorithm, the rest
// (x-neighbours and the u-w coupling of tau_xz) take their latest values:
//
//   T_l z_l = r_l - sum_{j not in line l} A_lj z_j,     lines ascending, then descending.
//
// The forward-backward pair makes M symmetric, as CG requires.
#include "twod/line_relaxation.hpp"

#include <stdexcept>

namespace granbench::twod {

void LineRelaxation::setup(const SpMat& A, std::vector<std::vector<int>> lines) {
  lines_ = std::move(lines);
  const int n = int(A.rows());
  diag_.assign(n, -1);
  lower_.assign(n, -1);
  upper_.assign(n, -1);
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  auto position = [&](int row, int col) {
    for (int p = outer[row]; p < outer[row + 1]; ++p)
      if (inner[p] == col) return p;
    return -1;
  };
  for (const auto& line : lines_)
    for (std::size_t k = 0; k < line.size(); ++k) {
      const int r = line[k];
      diag_[r] = position(r, r);
      if (k > 0) lower_[r] = position(r, line[k - 1]);
      if (k + 1 < line.size()) upper_[r] = position(r, line[k + 1]);
      if (diag_[r] < 0) throw std::logic_error("LineRelaxation: missing diagonal");
    }
  row_start_.assign(n + 1, 0);
  off_pos_.clear();
  off_col_.clear();
  for (int r = 0; r < n; ++r) {
    for (int p = outer[r]; p < outer[r + 1]; ++p)
      if (p != diag_[r] && p != lower_[r] && p != upper_[r]) {
        off_pos_.push_back(p);
        off_col_.push_back(inner[p]);
      }
    row_start_[r + 1] = int(off_pos_.size());
  }
}

void LineRelaxation::factorise(const SpMat& A) {
  const double* val = A.valuePtr();
  cp_.resize(A.rows());
  inv_m_.resize(A.rows());
  for (const auto& line : lines_)
    for (std::size_t k = 0; k < line.size(); ++k) {
      const int row = line[k];
      const double a = lower_[row] >= 0 ? val[lower_[row]] : 0.0;
      const double c = upper_[row] >= 0 ? val[upper_[row]] : 0.0;
      const double m = val[diag_[row]] - (k > 0 ? a * cp_[line[k - 1]] : 0.0);
      inv_m_[row] = 1.0 / m;
      cp_[row] = c * inv_m_[row];
    }
}

void LineRelaxation::solve_line(const SpMat& A, const Eigen::VectorXd& r, Eigen::VectorXd& z,
                                std::size_t l) const {
  const auto& line = lines_[l];
  const int m = int(line.size());
  const double* val = A.valuePtr();
  double d_prev = 0.0;
  for (int k = 0; k < m; ++k) {  // forward elimination with the cached factors
    const int row = line[k];
    double rhs = r[row];
    for (int q = row_start_[row]; q < row_start_[row + 1]; ++q)
      rhs -= val[off_pos_[q]] * z[off_col_[q]];
    const double a = k > 0 ? val[lower_[row]] : 0.0;
    d_prev = (rhs - a * d_prev) * inv_m_[row];
    z[row] = d_prev;  // holds d'_k until the back substitution
  }
  for (int k = m - 2; k >= 0; --k) z[line[k]] -= cp_[line[k]] * z[line[k + 1]];
}

void LineRelaxation::precondition(const SpMat& A, const Eigen::VectorXd& r,
                                  Eigen::VectorXd& z) const {
  z.setZero(r.size());
  for (std::size_t l = 0; l < lines_.size(); ++l) solve_line(A, r, z, l);
  for (std::size_t l = lines_.size(); l-- > 0;) solve_line(A, r, z, l);
}

}  // namespace granbench::twod

// Symmetric block (line) Gauss-Seidel as a conjugate-gradient preconditioner for the viscous
// system (viscous_step.cpp). The unknowns of each grid column (u's, and separately w's) form a
// line; the couplings along the line - the stiff ones, since dz < dx and the viscosity jumps at
// the free surface across the columns - are solved exactly with the Thomas algorithm, the rest
// (x-neighbours and the u-w coupling of tau_xz) take their latest values:
//
//   T_l z_l = r_l - sum_{j not in line l} A_lj z_j,     lines ascending, then descending.
//
// The forward-backward pair makes M symmetric, as CG requires.
#include "line_relaxation.hpp"

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
}

void LineRelaxation::solve_line(const SpMat& A, const Eigen::VectorXd& r, Eigen::VectorXd& z,
                                std::size_t l) const {
  const auto& line = lines_[l];
  const int m = int(line.size());
  thread_local std::vector<double> cp, dp;
  cp.resize(m);
  dp.resize(m);
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const double* val = A.valuePtr();
  for (int k = 0; k < m; ++k) {
    const int row = line[k];
    double rhs = r[row];
    const int pd = diag_[row], pl = lower_[row], pu = upper_[row];
    for (int p = outer[row]; p < outer[row + 1]; ++p)
      if (p != pd && p != pl && p != pu) rhs -= val[p] * z[inner[p]];
    const double a = pl >= 0 ? val[pl] : 0.0, c = pu >= 0 ? val[pu] : 0.0;
    const double denom = val[pd] - (k > 0 ? a * cp[k - 1] : 0.0);
    cp[k] = c / denom;
    dp[k] = (rhs - (k > 0 ? a * dp[k - 1] : 0.0)) / denom;
  }
  z[line[m - 1]] = dp[m - 1];
  for (int k = m - 2; k >= 0; --k) z[line[k]] = dp[k] - cp[k] * z[line[k + 1]];
}

void LineRelaxation::precondition(const SpMat& A, const Eigen::VectorXd& r,
                                  Eigen::VectorXd& z) const {
  z.setZero(r.size());
  for (std::size_t l = 0; l < lines_.size(); ++l) solve_line(A, r, z, l);
  for (std::size_t l = lines_.size(); l-- > 0;) solve_line(A, r, z, l);
}

}  // namespace granbench::twod

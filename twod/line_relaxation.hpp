// Symmetric line Gauss-Seidel preconditioner for a sparse SPD matrix whose unknowns are grouped
// into lines (line_relaxation.cpp).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

namespace granbench::twod {

using SpMat = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

class LineRelaxation {
 public:
  // lines: the row indices of each line, consecutive rows of a line coupled tridiagonally.
  // Call once the pattern of A is fixed (positions are cached; values are read at each use).
  void setup(const SpMat& A, std::vector<std::vector<int>> lines);
  bool ready() const { return !lines_.empty(); }
  // Factorise the line (tridiagonal) blocks of A once per solve.
  void factorise(const SpMat& A);
  // z = M^{-1} r: one forward and one backward sweep over the lines, starting from z = 0.
  void precondition(const SpMat& A, const Eigen::VectorXd& r, Eigen::VectorXd& z) const;

 private:
  void solve_line(const SpMat& A, const Eigen::VectorXd& r, Eigen::VectorXd& z,
                  std::size_t line) const;
  std::vector<std::vector<int>> lines_;
  // Per row: CSR positions of the diagonal and of the line neighbours below/above (-1: none).
  std::vector<int> diag_, lower_, upper_;
  // Per row: the CSR positions and columns of the couplings outside the line (row_start_ CSR).
  std::vector<int> row_start_, off_pos_, off_col_;
  // Thomas factors of the line blocks: c'_k and 1/m_k per row.
  std::vector<double> cp_, inv_m_;
};

}  // namespace granbench::twod

// Fixed-pattern assembly and the preconditioned conjugate-gradient solves (see spd_solver.hpp).
#include "twod/spd_solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "twod/pcg.hpp"

namespace granbench::twod {

void PatternedMatrix::begin(int n) {
  count_ = 0;
  if (fixed_) {
    if (A_.rows() != n)
      throw std::logic_error("PatternedMatrix: size changed after first assembly");
    values_ = A_.valuePtr();
    std::fill(values_, values_ + A_.nonZeros(), 0.0);
  } else {
    A_.resize(n, n);
    rows_.clear();
    cols_.clear();
    first_values_.clear();
  }
}

void PatternedMatrix::end() {
  if (fixed_) {
    if (count_ != slot_.size())
      throw std::logic_error("PatternedMatrix: assembly sequence changed");
    return;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(rows_.size());
  for (std::size_t k = 0; k < rows_.size(); ++k) triplets.emplace_back(rows_[k], cols_[k], 0.0);
  A_.setFromTriplets(triplets.begin(), triplets.end());
  A_.makeCompressed();
  // Map each add() of the sequence to its position in the CSR value array.
  slot_.resize(rows_.size());
  const int* outer = A_.outerIndexPtr();
  const int* inner = A_.innerIndexPtr();
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    const int* lo = inner + outer[rows_[k]];
    const int* hi = inner + outer[rows_[k] + 1];
    slot_[k] = int(std::lower_bound(lo, hi, cols_[k]) - inner);
  }
  fixed_ = true;
  values_ = A_.valuePtr();
  std::fill(values_, values_ + A_.nonZeros(), 0.0);
  for (std::size_t k = 0; k < rows_.size(); ++k) values_[slot_[k]] += first_values_[k];
  rows_ = {};
  cols_ = {};
  first_values_ = {};
}

void SpdSolver::factorise(const SpMat& A) {
  const Eigen::SparseMatrix<double> Ac = A;  // column-major copy for SimplicialLLT
  if (!analysed_) {
    llt_.analyzePattern(Ac);
    analysed_ = true;
  }
  llt_.factorize(Ac);
  if (llt_.info() != Eigen::Success)
    throw std::runtime_error("sparse Cholesky factorisation failed (matrix not positive definite)");
  factor_ready_ = true;
  ++stats_.factorisations;
}

int SpdSolver::run(const SpMat& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   int max_iterations) {
  auto apply = [&](const Eigen::VectorXd& v, Eigen::VectorXd& y) { y.noalias() = A * v; };
  switch (kind_) {
    case LinearSolverKind::Jacobi:
      return pcg(
          apply,
          [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = inv_diag_.cwiseProduct(r); }, b,
          x, tol_, max_iterations, work_);
    case LinearSolverKind::LineRelaxation:
      return pcg(
          apply, [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { line_.precondition(A, r, z); },
          b, x, tol_, max_iterations, work_);
    default:
      return pcg(
          apply, [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = llt_.solve(r); }, b, x,
          tol_, max_iterations, work_);
  }
}

int SpdSolver::solve(const SpMat& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  ++stats_.solves;
  int it = 0;
  switch (kind_) {
    case LinearSolverKind::Direct:
      factorise(A);
      it = run(A, b, x, 50);  // one iteration with the exact factor; more polish round-off
      break;
    case LinearSolverKind::Jacobi:
      inv_diag_ = A.diagonal().cwiseInverse();
      it = run(A, b, x, 20 * int(b.size()));
      break;
    case LinearSolverKind::LineRelaxation:
    case LinearSolverKind::Multigrid:  // (multigrid is matrix-free, in the projection)
      if (!line_.ready()) line_.setup(A, lines_);
      line_.factorise(A);
      it = run(A, b, x, 2000);
      break;
    case LinearSolverKind::StaleCholesky:
      if (!factor_ready_) factorise(A);
      it = run(A, b, x, 4 * refresh_);
      if (it < 0) {  // the old factor no longer fits: refactorise and solve again
        factorise(A);
        it = run(A, b, x, 50);
      } else if (it > refresh_) {
        factor_ready_ = false;  // refresh before the next solve
      }
      break;
  }
  if (it < 0) throw std::runtime_error("conjugate gradients did not converge");
  stats_.iterations += it;
  return it;
}

}  // namespace granbench::twod

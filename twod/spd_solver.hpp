// Sparse symmetric positive-definite systems of the 2D solver (viscous step, projection).
//
// PatternedMatrix assembles A from a deterministic sequence of add(row, col, value) calls: the
// first assembly fixes the sparsity pattern (Eigen CSR), later ones only refill the values in
// place, so the pattern - and with it the fill-reducing ordering of a Cholesky factorisation -
// is computed once.
//
// SpdSolver solves A x = b to a relative residual ||b - A x|| <= tol ||b||:
//   StaleCholesky  preconditioned conjugate gradients, the preconditioner being the exact
//                  Cholesky factor L L^T of an earlier A (Eigen SimplicialLLT). While the
//                  coefficients change slowly (eta, rho move with the flow) a factor stays an
//                  excellent preconditioner for many steps; it is refreshed when PCG needs more
//                  than `refresh_iterations`.
//   Direct         factorise every solve (exact to round-off).
//   Jacobi         conjugate gradients with the diagonal as preconditioner.
//   LineRelaxation conjugate gradients with symmetric line Gauss-Seidel (line_relaxation.hpp);
//                  the lines are given with set_lines().
#pragma once

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cstddef>
#include <vector>

#include "twod/line_relaxation.hpp"
#include "twod/parameters.hpp"
#include "twod/pcg.hpp"

namespace granbench::twod {

class PatternedMatrix {
 public:
  // Start an assembly of an n x n matrix; every add() must follow the same sequence each time.
  void begin(int n);
  void add(int row, int col, double value) {
    if (fixed_) {
      values_[slot_[count_++]] += value;
    } else {
      rows_.push_back(row);
      cols_.push_back(col);
      first_values_.push_back(value);
      ++count_;
    }
  }
  void end();
  const SpMat& matrix() const { return A_; }

 private:
  SpMat A_;
  bool fixed_ = false;
  double* values_ = nullptr;
  std::size_t count_ = 0;
  std::vector<int> rows_, cols_, slot_;
  std::vector<double> first_values_;
};

struct SolveStats {
  long solves = 0;
  long iterations = 0;
  long factorisations = 0;
};

class SpdSolver {
 public:
  SpdSolver(LinearSolverKind kind = LinearSolverKind::StaleCholesky, double tolerance = 1e-10,
            int refresh_iterations = 12)
      : kind_(kind), tol_(tolerance), refresh_(refresh_iterations) {}
  // Solve A x = b; x holds the initial guess on entry. Returns the PCG iterations used.
  int solve(const SpMat& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);
  const SolveStats& stats() const { return stats_; }
  // The relative residual of the next solves (the constructor's until set).
  void set_tolerance(double tolerance) { tol_ = tolerance; }
  // The lines of the LineRelaxation preconditioner (row indices along each grid column).
  void set_lines(std::vector<std::vector<int>> lines) { lines_ = std::move(lines); }

 private:
  void factorise(const SpMat& A);
  int run(const SpMat& A, const Eigen::VectorXd& b, Eigen::VectorXd& x, int max_iterations);

  LinearSolverKind kind_;
  double tol_;
  int refresh_;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt_;
  bool analysed_ = false, factor_ready_ = false;
  Eigen::VectorXd inv_diag_;
  std::vector<std::vector<int>> lines_;
  LineRelaxation line_;
  SolveStats stats_;
  PcgWorkspace work_;  // conjugate-gradient vectors, reused across solves
};

}  // namespace granbench::twod

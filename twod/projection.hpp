// The variable-density pressure projection (projection.cpp).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "twod/fields.hpp"
#include "twod/grid.hpp"
#include "twod/parameters.hpp"
#include "twod/pressure_multigrid.hpp"
#include "twod/spd_solver.hpp"

namespace granbench::twod {

// The multigrid's finest operator for the densities of props: -div((1/rho) grad dp) V on the
// cells, face by face (area / distance / rho), no flux through the bed, dp = 0 at the top.
// op must be sized nx x nz (PressureMultigrid::fine_operator).
void fill_pressure_operator(const Grid& g, const Properties& props, PoissonLevel& op);

class Projection {
 public:
  Projection(const Grid& g, const SolverParams& params);
  // Make (u*, w*) divergence free with the densities of props; u, w, p of s receive
  // u^{n+1}, w^{n+1}, p^{n+1} = p^n + delta p. Returns the solver iterations.
  int project(const std::vector<double>& u_star, const std::vector<double>& w_star,
              const Properties& props, double dt, Fields& s);
  // The initial guess of the next solve (the last pressure increment), for checkpoints.
  const Eigen::VectorXd& warm_start() const { return x_; }
  void set_warm_start(Eigen::VectorXd x) { x_ = std::move(x); }
  const SolveStats& stats() const {
    return kind_ == LinearSolverKind::Multigrid ? mg_stats_ : solver_.stats();
  }

 private:
  Grid g_;
  LinearSolverKind kind_;
  double tol_;
  PressureMultigrid multigrid_;
  SolveStats mg_stats_;
  PatternedMatrix A_;
  SpdSolver solver_;
  Eigen::VectorXd b_, x_;
  PcgWorkspace work_;  // conjugate-gradient vectors, reused across steps
};

// Discrete divergence (u_{i+1} - u_i)/dx + (w_{k+1} - w_k)/dz of cell (i, k).
double cell_divergence(const Grid& g, const std::vector<double>& u, const std::vector<double>& w,
                       int i, int k);
// The same from a row's u, the w of its lower and upper faces and the column ip = i + 1 (0 for
// the last): the form a loop over a row vectorises.
inline double cell_divergence(const double* u_row, const double* w_below, const double* w_above,
                              int i, int ip, double dx, double dz) {
  return (u_row[ip] - u_row[i]) / dx + (w_above[i] - w_below[i]) / dz;
}

}  // namespace granbench::twod

// The matrix of the backward-Euler viscous step (viscous_step.cpp) as a structured stencil on
// the MAC grid, applied without assembling it, and its symmetric z-line Gauss-Seidel
// preconditioner (viscous_operator.cpp).
//
// Unknowns: the u's of column i at i nz + k (0 <= k < nz), then the interior w's of column i at
// nx nz + i (nz - 1) + (k - 1) (1 <= k < nz); a column's u's (and its w's) form one line.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "twod/fields.hpp"
#include "twod/grid.hpp"
#include "twod/spd_solver.hpp"

namespace granbench::twod {

class ViscousOperator {
 public:
  explicit ViscousOperator(const Grid& g);
  int size() const { return nu_ + g_.nx * (g_.nz - 1); }
  int u_index(int i, int k) const { return g_.wrap(i) * g_.nz + k; }
  int w_index(int i, int k) const { return nu_ + g_.wrap(i) * (g_.nz - 1) + (k - 1); }

  // Coefficients for one step: the face masses rho V / dt and the stress weights 2 eta_c V
  // (cells) and eta_n V (corners) from the properties at the new level; then the Thomas factors
  // of the lines. The first form takes props.eta_c, props.eta_n.
  void set(const Properties& props, double dt);
  void set(const Properties& props, const std::vector<double>& eta_c,
           const std::vector<double>& eta_n, double dt);
  // The stress weights alone (no mass terms, no line factors): apply() is then the stress part
  // of the operator with these viscosities, for a stress taken explicitly.
  void set_stress(const std::vector<double>& eta_c, const std::vector<double>& eta_n);
  // y = A x.
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // z = M^{-1} r: one sweep over the lines (u-lines, then w-lines, each in blocks of columns:
  // the even blocks, then the odd ones, columns ascending in a block) and one in exactly the
  // reverse order, from z = 0, so that M is symmetric. Blocks of one colour are swept in
  // parallel (see the .cpp).
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  // The same matrix assembled (for the sparse-matrix preconditioners of SpdSolver).
  void assemble(PatternedMatrix& A) const;

 private:
  // The stress weights kc_, kn_ from the viscosities (set and set_stress).
  void set_stress_weights(const std::vector<double>& eta_c, const std::vector<double>& eta_n);
  // Where a matrix entry sits relative to its row's line: the diagonal, the line neighbour
  // below or above, or outside the line.
  enum class Entry { Diag, Lower, Upper, Off };
  template <class Visit>
  void visit_u_row(int i, int k, Visit&& visit) const;
  template <class Visit>
  void visit_w_row(int i, int k, Visit&& visit) const;
  // each(row, entries) for every row in index order; entries(visit) visits that row.
  template <class Each>
  void for_each_row(Each&& each) const;
  // The n lines of length `length` from the rows `first`, in place: z holds their right-hand
  // sides.
  template <int n>
  void solve_lines(const int (&first)[n], int length, Eigen::VectorXd& z) const;
  // The u-lines (or w-lines) of the n <= 4 independent columns: right-hand sides, then solves.
  void solve_column_lines(bool u_lines, const int* columns, int n, const Eigen::VectorXd& r,
                          Eigen::VectorXd& z) const;
  // One colour of blocks of one sweep of the preconditioner (see the .cpp).
  void sweep_colour(int colour, bool forward, bool u_lines, const Eigen::VectorXd& r,
                    Eigen::VectorXd& z) const;
  // Column i's u-line (w-line) right-hand side r minus its couplings outside the line, into z.
  void u_line_rhs(int i, const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  void w_line_rhs(int i, const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  // y's rows of column i's u's (w's): the product A x (each row written once)
  void apply_u_column(int i, const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  void apply_w_column(int i, const Eigen::VectorXd& x, Eigen::VectorXd& y) const;

  Grid g_;
  int nu_;
  double ixx_, izz_, ixz_;                  // 1/dx^2, 1/dz^2, 1/(dx dz)
  std::vector<double> mass_u_, mass_w_;     // rho V / dt on u- and interior w-faces
  std::vector<double> kc_, kn_;             // 2 eta_c V per cell, eta_n V per corner
  std::vector<double> lower_, inv_m_, cp_;  // Thomas factors per unknown
};

}  // namespace granbench::twod

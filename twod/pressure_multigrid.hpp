// Geometric multigrid for the variable-coefficient pressure equation of the projection
// (pressure_multigrid.cpp), used as the preconditioner of conjugate gradients.
#pragma once

#include <Eigen/Dense>
#include <utility>
#include <vector>

namespace granbench::twod {

// The cell-centred operator  (A p)_c = sum_faces c_f (p_c - p_nb) + c_top p_c  on an nx x nz
// grid, periodic in x, no flux through the bed, Dirichlet (p = 0) half a cell above the top row.
// Stored column by column (cell (i, k) at i nz + k) so that the z-lines are contiguous.
struct PoissonLevel {
  int nx = 0, nz = 0;
  bool halved_x_alone = false;  // a coarse level made from the finer one by halving nx alone
  std::vector<double> cx;       // x-face coefficients, face left of cell (i, k) at i nz + k
  std::vector<double> cz;       // z-face coefficients at i (nz + 1) + k, k = 0 (bed) .. nz (top)
  int cell(int i, int k) const { return i * nz + k; }
  int zface(int i, int k) const { return i * (nz + 1) + k; }
  // Thomas factors of the column blocks, set by factorise() for the columns outside the line
  // smoother's groups (below), which hold their own
  std::vector<double> cp, inv_m;
  // The same coefficients for the line smoother, by groups of kLineLanes columns of one colour
  // (columns c + 2 (kLineLanes g + j), lane j): entry ((c groups + g) nz + k) kLineLanes + j, so
  // that the group's columns are solved side by side in vector registers. Set by factorise()
  // when nx is even; `line_work` holds the forward sweep's values of each group.
  std::vector<double> line_cl, line_cr, line_cz, line_inv_m, line_cp;
  mutable std::vector<double> line_work;
  int line_groups = 0;  // groups per colour
  void factorise();
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
};

// The levels: a grid is halved while both counts are even, nz >= 4, nx >= 4 and it has more than
// 64 cells; a level whose cells are less than kCoarsenXAloneBelowAspect times as wide as tall
// (dx / dz) is halved along x alone (then nx even, nx >= 4 and more than 64 cells suffice). The
// coarsest is solved directly up to kDirectCoarsestCells cells and smoothed by line sweeps above
// (an odd count on a large grid), at several times the cost of a step.
inline constexpr int kDirectCoarsestCells = 2048;
inline constexpr int kLineLanes = 8;  // columns solved side by side (one AVX-512 register)
inline constexpr double kCoarsenXAloneBelowAspect = 2.0;
// (nx, nz) of the coarsest level for a fine grid of cells dx / dz = aspect
std::pair<int, int> coarsest_level(int nx, int nz, double aspect);

class PressureMultigrid {
 public:
  // Set the finest operator, on cells of dx / dz = aspect; coarse levels are rebuilt from it.
  void set_operator(const PoissonLevel& fine, double aspect);
  // The same without a copy: fill the coefficients of fine_operator(nx, nz, aspect) (the finest
  // level, sized and kept from one call to the next), then call rebuild().
  PoissonLevel& fine_operator(int nx, int nz, double aspect);
  void rebuild();
  const PoissonLevel& fine() const { return levels_.front(); }
  // z = M^{-1} r: one symmetric V(1,1)-cycle from z = 0.
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z);
  int levels() const { return int(levels_.size()); }

 private:
  void vcycle(std::size_t level, const Eigen::VectorXd& b, Eigen::VectorXd& x);
  void line_sweep(const PoissonLevel& L, const Eigen::VectorXd& b, Eigen::VectorXd& x, bool forward,
                  bool from_zero) const;

  std::vector<PoissonLevel> levels_;
  double aspect_ = 0.0;  // dx / dz of the finest level's cells
  std::vector<Eigen::VectorXd> rhs_c_, x_c_;
  Eigen::LDLT<Eigen::MatrixXd> coarsest_;
  bool direct_coarsest_ = true;
};

}  // namespace granbench::twod

// Incremental pressure projection with variable density (fractional step, Chorin-Temam with
// the pressure increment; Brown, Cortez & Minion 2001):
//
//   u^{n+1} = u* - (dt / rho^{n+1}) grad(dp),   div u^{n+1} = 0                    (2.9)
//   =>  div( (1/rho^{n+1}) grad(dp) ) = div(u*) / dt,    p^{n+1} = p^n + dp.
//
// Discretised on the MAC grid with rho on the faces (the same face densities as gravity and
// grad p^n in the predictor: balanced force). Multiplying by -V gives the symmetric positive
// definite system  sum_faces c_f (dp_c - dp_nb) = -V div(u*)/dt,  c_f = area/(dist rho_f).
// Boundaries: periodic in x; at the bed w = 0 (no correction, d(dp)/dz = 0); at the top
// p = 0, so dp = 0 at z = Lz, half a cell above the last centre.
// Solved by conjugate gradients preconditioned with geometric multigrid (pressure_multigrid.cpp,
// matrix-free) or, on request, with an assembled matrix and one of the sparse preconditioners.
#include "twod/projection.hpp"

#include <algorithm>
#include <stdexcept>

#include "twod/parallel.hpp"
#include "twod/pcg.hpp"
#include "twod/periodic_row.hpp"

namespace granbench::twod {

double cell_divergence(const Grid& g, const std::vector<double>& u, const std::vector<double>& w,
                       int i, int k) {
  const std::size_t row = std::size_t(k) * g.nx;
  return cell_divergence(u.data() + row, w.data() + row, w.data() + row + g.nx, i, g.wrap(i + 1),
                         g.dx, g.dz);
}

Projection::Projection(const Grid& g, const SolverParams& params)
    : g_(g),
      kind_(params.pressure_solver),
      tol_(params.solver_tolerance),
      solver_(params.pressure_solver, params.solver_tolerance) {
  std::vector<std::vector<int>> lines;  // columns, for the line-relaxation option
  for (int i = 0; i < g.nx; ++i) {
    std::vector<int> line;
    for (int k = 0; k < g.nz; ++k) line.push_back(i * g.nz + k);
    lines.push_back(std::move(line));
  }
  solver_.set_lines(std::move(lines));
}

void fill_pressure_operator(const Grid& g, const Properties& props, PoissonLevel& op) {
  const int nx = g.nx, nz = g.nz;
  const double cx = g.dz / g.dx, cz = g.dx / g.dz;  // area / distance
  parallel_for(nx, true, [&](int i) {
    for (int k = 0; k < nz; ++k) op.cx[op.cell(i, k)] = cx / props.rho_u[g.at(i, k)];
    op.cz[op.zface(i, 0)] = 0.0;  // bed: no flux
    for (int k = 1; k < nz; ++k) op.cz[op.zface(i, k)] = cz / props.rho_w[g.at(i, k)];
    op.cz[op.zface(i, nz)] = 2.0 * cz / props.rho_w[g.at(i, nz)];  // dp = 0 at top
  });
}

int Projection::project(const std::vector<double>& u_star, const std::vector<double>& w_star,
                        const Properties& props, double dt, Fields& s) {
  const Grid& g = g_;
  const int nx = g.nx, nz = g.nz, n = nx * nz;
  const double V = g.cell_volume();
  const double cx = g.dz / g.dx, cz = g.dx / g.dz;  // area / distance
  // Unknown of cell (i, k): i nz + k (column by column, as the multigrid stores it).
  auto id = [&](int i, int k) { return g.wrap(i) * nz + k; };
  b_.resize(n);
  if (x_.size() != n) x_.setZero(n);  // warm start: the previous step's increment
  // (grid loops parallel over rows or columns, each entry written once; parallel.hpp)
  parallel_for(nz, true, [&](int k) {  // row by row, vectorised (b_ written across the columns)
    const std::size_t row = std::size_t(k) * nx;
    const double *u = u_star.data() + row, *w = w_star.data() + row, *w_above = w + nx;
    double* b = b_.data() + k;
    const double dx = g.dx, dz = g.dz;
#pragma omp simd
    for (int i = 0; i < nx - 1; ++i)
      b[std::size_t(i) * nz] = -V * cell_divergence(u, w, w_above, i, i + 1, dx, dz) / dt;
    b[std::size_t(nx - 1) * nz] = -V * cell_divergence(u, w, w_above, nx - 1, 0, dx, dz) / dt;
  });
  int iterations = 0;
  if (kind_ == LinearSolverKind::Multigrid) {
    PoissonLevel& op = multigrid_.fine_operator(nx, nz, g.dx / g.dz);  // filled in place
    fill_pressure_operator(g, props, op);
    multigrid_.rebuild();
    iterations =
        pcg([&](const Eigen::VectorXd& v, Eigen::VectorXd& y) { op.apply(v, y); },
            [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { multigrid_.precondition(r, z); },
            b_, x_, tol_, 500, work_);
    if (iterations < 0) throw std::runtime_error("pressure multigrid-CG did not converge");
    ++mg_stats_.solves;
    mg_stats_.iterations += iterations;
  } else {
    A_.begin(n);
    auto pair = [&](int a, int b, double c) {
      A_.add(a, a, c);
      A_.add(a, b, -c);
      A_.add(b, b, c);
      A_.add(b, a, -c);
    };
    for (int k = 0; k < nz; ++k)
      for (int i = 0; i < nx; ++i) {
        const int c = id(i, k);
        pair(id(i - 1, k), c, cx / props.rho_u[g.at(i, k)]);                 // x-face (i, k)
        if (k > 0) pair(id(i, k - 1), c, cz / props.rho_w[g.at(i, k)]);      // z-face (i, k)
        if (k == nz - 1) A_.add(c, c, 2.0 * cz / props.rho_w[g.at(i, nz)]);  // dp = 0 at top
      }
    A_.end();
    iterations = solver_.solve(A_.matrix(), b_, x_);
  }

  // The corrections row by row, each row's faces in a loop that vectorises (the increments of
  // x are read across the columns: gathers; the divisions were most of these loops' time).
  const double* x = x_.data();
  const double dx = g.dx, dz = g.dz;
  parallel_for(nz, true, [&](int k) {
    const std::size_t row = std::size_t(k) * nx;
    const double *us = u_star.data() + row, *rho = props.rho_u.data() + row, *xk = x + k;
    double *u = s.u.data() + row, *p = s.p.data() + row;
    auto face = [=](int i, int il) {
      u[i] = us[i] - dt / rho[i] * (xk[std::size_t(i) * nz] - xk[std::size_t(il) * nz]) / dx;
      p[i] += xk[std::size_t(i) * nz];
    };
    for_columns_with_left(nx, 0, nx, [=](int il, int i) { face(i, il); });
  });
  parallel_for(nz + 1, true, [&](int k) {
    const std::size_t row = std::size_t(k) * nx;
    const double *ws = w_star.data() + row, *rho = props.rho_w.data() + row;
    double* w = s.w.data() + row;
    if (k == 0) {  // the bed
      std::fill_n(w, nx, 0.0);
    } else if (k == nz) {  // the top face: dp = 0 half a cell above the top cell's centre
      const double* x_below = x + (nz - 1);
#pragma omp simd
      for (int i = 0; i < nx; ++i)
        w[i] = ws[i] - dt / rho[i] * (0.0 - x_below[std::size_t(i) * nz]) / (0.5 * dz);
    } else {
      const double *x_here = x + k, *x_below = x + (k - 1);
#pragma omp simd
      for (int i = 0; i < nx; ++i)
        w[i] =
            ws[i] - dt / rho[i] * (x_here[std::size_t(i) * nz] - x_below[std::size_t(i) * nz]) / dz;
    }
  });
  return iterations;
}

}  // namespace granbench::twod

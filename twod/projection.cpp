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
#include "projection.hpp"

namespace granbench::twod {

double cell_divergence(const Grid& g, const std::vector<double>& u, const std::vector<double>& w,
                       int i, int k) {
  return (u[g.at(i + 1, k)] - u[g.at(i, k)]) / g.dx + (w[g.at(i, k + 1)] - w[g.at(i, k)]) / g.dz;
}

Projection::Projection(const Grid& g, const SolverParams& params)
    : g_(g), solver_(params.linear_solver, params.solver_tolerance) {}

int Projection::project(const std::vector<double>& u_star, const std::vector<double>& w_star,
                        const Properties& props, double dt, Fields& s) {
  const Grid& g = g_;
  const int nx = g.nx, nz = g.nz, n = nx * nz;
  const double V = g.cell_volume();
  const double cx = g.dz / g.dx, cz = g.dx / g.dz;  // area / distance
  b_.resize(n);
  x_.setZero(n);
  A_.begin(n);
  auto pair = [&](int a, int b, double c) {
    A_.add(a, a, c);
    A_.add(a, b, -c);
    A_.add(b, b, c);
    A_.add(b, a, -c);
  };
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const int c = int(g.at(i, k));
      b_[c] = -V * cell_divergence(g, u_star, w_star, i, k) / dt;
      pair(int(g.at(i - 1, k)), c, cx / props.rho_u[c]);                // x-face (i, k)
      if (k > 0) pair(int(g.at(i, k - 1)), c, cz / props.rho_w[c]);     // z-face (i, k)
      if (k == nz - 1) A_.add(c, c, 2.0 * cz / props.rho_w[g.at(i, nz)]);  // dp = 0 at top
    }
  A_.end();
  const int iterations = solver_.solve(A_.matrix(), b_, x_);

  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const std::size_t c = g.at(i, k);
      s.u[c] = u_star[c] - dt / props.rho_u[c] * (x_[c] - x_[g.at(i - 1, k)]) / g.dx;
      s.p[c] += x_[c];
    }
  for (int i = 0; i < nx; ++i) {
    s.w[g.at(i, 0)] = 0.0;
    for (int k = 1; k < nz; ++k) {
      const std::size_t c = g.at(i, k);
      s.w[c] = w_star[c] - dt / props.rho_w[c] * (x_[c] - x_[g.at(i, k - 1)]) / g.dz;
    }
    const std::size_t top = g.at(i, nz);
    s.w[top] = w_star[top] - dt / props.rho_w[top] * (0.0 - x_[g.at(i, nz - 1)]) / (0.5 * g.dz);
  }
  return iterations;
}

}  // namespace granbench::twod

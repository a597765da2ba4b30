// Backward-Euler momentum predictor with the full viscous stress tensor, (2.10):
//
//   rho^{n+1} (u* - u^n)/dt = div(2 eta D(u*)) - grad p^n + rho^{n+1} (g - (u^n . grad) u^n),
//   g = (g sin zeta, -g cos zeta),
//
// eta from the previous step (properties.cpp). Because eta ranges over ~1e8 between grains and
// light fluid, the stress is fully implicit and u, w are coupled through tau_xz. Written on the
// MAC control volumes (volume V = dx dz), the stress work is a sum of squares,
//   cells:    2 eta_c V (D_xx^2 + D_zz^2),  D_xx = (u_{i+1} - u_i)/dx, D_zz = (w_{k+1} - w_k)/dz,
//   corners:  eta_n V gamma^2,              gamma = (u_k - u_{k-1})/dz + (w_i - w_{i-1})/dx,
// so each term adds K a a^T to the matrix (a: the difference stencil, K = 2 eta V or eta V) and
// the system  (rho V/dt) u* - V div(2 eta D(u*)) = rhs  is symmetric positive definite.
// Boundaries: at the bed u* ghost = -u* (gamma = 2u/dz on a half volume) and w = 0; at the top
// du/dz = 0, with the top w (and its dw/dx in tau_xz) lagged at w^n.
// The pressure gradient and gravity sit on the same faces with the same rho as in the projection
// (balanced force), so a hydrostatic p^n cancels gravity exactly.
#include "viscous_step.hpp"

#include <cmath>

namespace granbench::twod {

ViscousStep::ViscousStep(const Grid& g, const SolverParams& params)
    : g_(g), gx_(params.rheology.material.g * std::sin(params.zeta)),
      gz_(-params.rheology.material.g * std::cos(params.zeta)),
      solver_(params.viscous_solver, params.viscous_tolerance) {
  // Lines for the line-relaxation preconditioner: the u's and the w's of each column.
  const int nx = g.nx, nz = g.nz, nu = nx * nz;
  std::vector<std::vector<int>> lines;
  for (int i = 0; i < nx; ++i) {
    std::vector<int> line;
    for (int k = 0; k < nz; ++k) line.push_back(i * nz + k);
    lines.push_back(std::move(line));
  }
  for (int i = 0; i < nx; ++i) {
    std::vector<int> line;
    for (int k = 1; k < nz; ++k) line.push_back(nu + i * (nz - 1) + (k - 1));
    lines.push_back(std::move(line));
  }
  solver_.set_lines(std::move(lines));
}

int ViscousStep::predict(const Fields& s, const Properties& props,
                         const std::vector<double>& adv_u, const std::vector<double>& adv_w,
                         double dt, std::vector<double>& u_star, std::vector<double>& w_star) {
  const Grid& g = g_;
  const int nx = g.nx, nz = g.nz;
  const int nu = nx * nz, n = nu + nx * (nz - 1);
  const double V = g.cell_volume();
  // Unknowns column by column (the lines of the preconditioner are contiguous in memory).
  auto iu = [&](int i, int k) { return g.wrap(i) * nz + k; };
  auto iw = [&](int i, int k) { return nu + g.wrap(i) * (nz - 1) + (k - 1); };  // 1 <= k < nz

  b_.setZero(n);
  x_.resize(n);
  A_.begin(n);
  // Mass terms and explicit right-hand side.
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const std::size_t c = g.at(i, k);
      const double m = props.rho_u[c] * V;
      A_.add(iu(i, k), iu(i, k), m / dt);
      b_[iu(i, k)] = m * (s.u[c] / dt - adv_u[c] + gx_) - g.dz * (s.p[c] - s.p[g.at(i - 1, k)]);
      x_[iu(i, k)] = s.u[c];
    }
  for (int k = 1; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const std::size_t c = g.at(i, k);
      const double m = props.rho_w[c] * V;
      A_.add(iw(i, k), iw(i, k), m / dt);
      b_[iw(i, k)] = m * (s.w[c] / dt - adv_w[c] + gz_) - g.dx * (s.p[c] - s.p[g.at(i, k - 1)]);
      x_[iw(i, k)] = s.w[c];
    }
  // K a a^T for a stencil of up to four entries; index < 0 marks a known value.
  struct Entry {
    int index;
    double a;
    double known;
  };
  auto stencil = [&](double K, std::initializer_list<Entry> e) {
    for (const Entry& r : e) {
      if (r.index < 0) continue;
      for (const Entry& c : e) {
        if (c.index >= 0)
          A_.add(r.index, c.index, K * r.a * c.a);
        else
          b_[r.index] -= K * r.a * c.a * c.known;
      }
    }
  };
  const double ix = 1.0 / g.dx, iz = 1.0 / g.dz;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const double K = 2.0 * props.eta_c[g.at(i, k)] * V;
      stencil(K, {{iu(i + 1, k), ix, 0.0}, {iu(i, k), -ix, 0.0}});  // tau_xx
      const Entry top = k + 1 < nz ? Entry{iw(i, k + 1), iz, 0.0}
                                   : Entry{-1, iz, s.w[g.at(i, nz)]};
      const Entry bottom = k > 0 ? Entry{iw(i, k), -iz, 0.0} : Entry{-1, -iz, 0.0};
      stencil(K, {top, bottom});  // tau_zz
    }
  for (int i = 0; i < nx; ++i)  // tau_xz on the bed: gamma = 2 u_0/dz over half a volume
    stencil(0.5 * props.eta_n[g.at(i, 0)] * V, {{iu(i, 0), 2.0 * iz, 0.0}});
  for (int k = 1; k < nz; ++k)
    for (int i = 0; i < nx; ++i)
      stencil(props.eta_n[g.at(i, k)] * V, {{iu(i, k), iz, 0.0},
                                            {iu(i, k - 1), -iz, 0.0},
                                            {iw(i, k), ix, 0.0},
                                            {iw(i - 1, k), -ix, 0.0}});
  for (int i = 0; i < nx; ++i) {  // tau_xz on the top with du/dz = 0 and lagged w
    const double tau = props.eta_n[g.at(i, nz)] * (s.w[g.at(i, nz)] - s.w[g.at(i - 1, nz)]) * ix;
    b_[iu(i, nz - 1)] += g.dx * tau;
  }
  A_.end();

  const int iterations = solver_.solve(A_.matrix(), b_, x_);
  u_star.resize(g.cells());
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) u_star[g.at(i, k)] = x_[iu(i, k)];
  w_star.assign(g.w_faces(), 0.0);
  for (int k = 1; k < nz; ++k)
    for (int i = 0; i < nx; ++i) w_star[g.at(i, k)] = x_[iw(i, k)];
  for (int i = 0; i < nx; ++i) w_star[g.at(i, nz)] = w_star[g.at(i, nz - 1)];  // dw/dz = 0
  return iterations;
}

}  // namespace granbench::twod

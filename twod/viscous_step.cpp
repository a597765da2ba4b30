// Backward-Euler momentum predictor with the full viscous stress tensor, (2.10):
//
//   rho^{n+1} (u* - u^n)/dt = div(2 eta D(u*)) - grad p^n + rho^{n+1} (g - (u^n . grad) u^n),
//   g = (g sin zeta, -g cos zeta),
//
// less, along x, the ambient pressure gradient rho_l g sin zeta (Rheology::
// ambient_pressure_gradient): the light fluid's hydrostatic gradient along the slope, which the
// periodic domain cannot hold as a pressure difference between its ends. Without it the light
// layer is a stream driven down the slope by its own weight against its small viscosity,
//   u_l(z) - u_s = (rho_l g sin zeta / eta_l) (H (z - h) - (z - h)^2 / 2),  H = Lz - h,
// 0.06 m/s faster than the surface at the lid, and its shear rate, 28 1/s at the surface,
// times the one-row step that the light fluid's lowest row makes where the surface crosses a
// cell face, drove a first-mode light flow of 2e-3 m/s at any wave amplitude, which the films
// of grains at the crests followed (docs/twod-validation.md §4, "Wisps at a face").
//
// where a face has lost mass in the interface's move, grad p^n enters as the acceleration it gave,
// (rho^{n+1}/rho^n) grad p^n, and the rest after the solve (predict(); SolverParams::
// predictor_pressure_acceleration),
// with the stress linearised about u^n (SolverParams::viscosity_tangent, the default):
//
//   tau^{n+1} = tau(D^n, p*) + C^n : (D* - D^n)  ~  2 eta_t D* + 2 (eta - eta_t) D^n,
//
// eta the secant and eta_t the tangent viscosities at the new level (properties.cpp), p* the
// pressure extrapolated to it (solver.cpp). For a perturbation of a steady flow this is the
// linearised stress at the new level, so the step has no first-order lag; the matrix keeps eta_t,
// and S(eta - eta_t) u^n moves to the right-hand side. Without the tangent, eta is the secant
// from u^n (lagged one step). Because eta ranges over ~1e8 between grains and
// light fluid, the stress is fully implicit and u, w are coupled through tau_xz. Written on the
// MAC control volumes (volume V = dx dz), the stress work is a sum of squares,
//   cells:    2 eta_c V (D_xx^2 + D_zz^2),  D_xx = (u_{i+1} - u_i)/dx, D_zz = (w_{k+1} - w_k)/dz,
//   corners:  eta_n V gamma^2,              gamma = (u_k - u_{k-1})/dz + (w_i - w_{i-1})/dx,
// so each term adds K a a^T to the matrix (a: the difference stencil, K = 2 eta V or eta V) and
// the system  (rho V/dt) u* - V div(2 eta D(u*)) = rhs  is symmetric positive definite. Its rows
// are written out in viscous_operator.cpp; with the default line-relaxation preconditioner it
// is never assembled.
// Boundaries: at the bed u* ghost = 2 u_bed - u* (gamma = 2 (u - u_bed)/dz on a half volume; u_bed
// = 0 unless the grid moves) and w = 0; at the top
// du/dz = 0, with the top w (and its dw/dx in tau_xz) lagged at w^n; the top face's w* takes the
// face below's tendencies and its own pressure force, to p = 0 at z = Lz (end of predict()).
// The pressure gradient and gravity sit on the same faces with the same rho as in the projection
// (balanced force), so a hydrostatic p^n cancels gravity exactly.
#include "twod/viscous_step.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "twod/explicit_stress_limit.hpp"
#include "twod/parallel.hpp"
#include "twod/pcg.hpp"
#include "twod/periodic_row.hpp"

namespace granbench::twod {

double viscous_stop_tolerance(double tolerance, double change, double b_norm) {
  // Relative to the residual of the old velocity, i.e. to the change this step makes, not to
  // ||b||: ||b|| holds rho u^n / dt, so against it a small perturbation's change, and at small
  // steps any change, fell below the tolerance; at cfl 0.1 with a 2.5e-6 m seed most steps took
  // the extrapolated initial guess unsolved and the section 7 growth came out 4 % high
  // (docs/twod-validation.md §2). But never looser than 1e-8 ||b|| (the rule before that): a step
  // whose change is large (a splash, a droplet thrown off the front) would otherwise stop at 1e-4
  // of that change, and the 12 cm eigenmode rollwave diverged at 7.3 s so. The floor (a
  // round-off level of ||b||) ends the iteration where the old velocity is already a solution.
  constexpr double kLoosest = 1e-8, kRoundOff = 1e-12;
  if (!(b_norm > 0.0)) return tolerance;
  return std::max(std::min(tolerance * change / b_norm, kLoosest), kRoundOff);
}

ViscousStep::ViscousStep(const Grid& g, const SolverParams& params)
    : g_(g),
      gx_(params.rheology.material.g * std::sin(params.zeta)),
      gz_(-params.rheology.material.g * std::cos(params.zeta)),
      rho_ambient_(params.rheology.ambient_pressure_gradient ? params.rheology.rho_light : 0.0),
      kind_(params.viscous_solver),
      tol_(params.viscous_tolerance),
      tangent_(params.viscosity_tangent),
      pressure_acceleration_(params.predictor_pressure_acceleration),
      acceleration_limit_(params.predictor_acceleration_limit * params.rheology.material.g),
      op_(g),
      explicit_stress_(g),
      solver_(params.viscous_solver, params.viscous_tolerance) {}

void ViscousStep::as_unknowns(const Fields& f, Eigen::VectorXd& v) const {
  const Grid& g = g_;
  v.resize(op_.size());
  parallel_for(g.nz, true, [&](int k) {
    for (int i = 0; i < g.nx; ++i) v[op_.u_index(i, k)] = f.u[g.at(i, k)];
  });
  parallel_for(g.nz - 1, true, [&](int k_from_1) {
    const int k = k_from_1 + 1;
    for (int i = 0; i < g.nx; ++i) v[op_.w_index(i, k)] = f.w[g.at(i, k)];
  });
}

int ViscousStep::predict(const Fields& s, const Properties& props, const std::vector<double>& adv_u,
                         const std::vector<double>& adv_w, double dt, std::vector<double>& u_star,
                         std::vector<double>& w_star, const std::vector<double>& force_u,
                         const std::vector<double>& force_w, const Fields* about) {
  const Grid& g = g_;
  const int nx = g.nx, nz = g.nz;
  const double V = g.cell_volume();
  if (tangent_) {
    // The implicit part: the tangent, unless that leaves more explicit stress than the lightest
    // face beside a stress point can carry (explicit_stress_limit.hpp). At low I the tangent
    // ratio Gamma/mu -> 0 while eta reaches eta_max: in a layer coming to rest (§5.2, eta_max =
    // 1e7 Pa s) the whole yield stress was then explicit, mu p sign(D^n), and the layer started
    // to move again on a slope below mu_s.
    implicit_viscosities(g, props, dt, implicit_c_, implicit_n_);
    op_.set(props, implicit_c_, implicit_n_, dt);
  } else
    op_.set(props, dt);
  // Initial guess u^n + (dt/dt_prev)(u* - u^n)_prev: the predictor increment changes slowly
  // from step to step, and starting from it halves the iterations against starting from u^n.
  const bool have_increment = increment_.size() == op_.size() && dt_previous_ > 0.0;
  const double guess_scale = have_increment ? dt / dt_previous_ : 0.0;
  b_.resize(op_.size());  // every entry is written below
  x_.resize(op_.size());
  // Mass terms, gravity, pressure gradient and advection; the initial guess is u^n. (Loops over
  // rows in parallel: each entry is written once; parallel.hpp.)
  // p^n was balanced against the face densities of the step before, rho^n. Where the interface's
  // move has emptied a face (a droplet of grains falling away, a cap over a pocket), grad p^n
  // is the grains' pressure gradient, and as a force on the light fluid left there it is up
  // to 10^5 times its weight. The implicit stress spread that kick into the grains next to the
  // face before the projection could take it back, and left it there as a vortex: that is how
  // the 12 cm sine rollwave ran away (docs/twod-validation.md §10, last subsection). So where a
  // face has lost mass the solve below carries the acceleration p^n gave, grad p^n / rho^n, i.e.
  // the force times rho^{n+1} / rho^n, and the rest, (1/rho^{n+1} - 1/rho^n) grad p^n, is added to
  // u* after it, unspread; u* then holds the whole dt grad p^n / rho^{n+1} of the incremental
  // projection, as before, and the predictor differs from the former one only by what the
  // stress does to that rest. Where a face has gained mass the force stays: the light fluid's
  // pressure gradient times rho^{n+1} / rho^n would be the same kick on the grains now there,
  // spread the same way (a coarse saturated rollwave then ran at four times its flux). Where
  // rho is unchanged the factor is 1 exactly and the rest 0, so nothing changes there.
  //
  // The same holds for a face that stays light while the grains around it hold it: a film of
  // light fluid between grains (the floor of a pocket under an overturned front) keeps the
  // grains' pressure gradient, balanced by the stress of its granular corners, not by its own
  // mass. The solve spreads that force into the grains too; next to a face that has just been
  // emptied (whose rest goes to u* unspread) the two no longer add up to a gradient, and the
  // projection leaves the difference as a vortex: the 12 cm sine rollwave at 48 cells per h0
  // went from 0.6 to 52 m/s in one step at 4.76 s (docs/twod-validation.md §11 item 9). So the
  // solve carries at most the acceleration acceleration_limit_ (100 g by default; gravity and
  // the bulk flow's accelerations stay below it), and the rest joins the emptied faces' rest.
  // Whatever the split, u* holds the whole dt grad p^n / rho^{n+1} after the rest is added, and
  // the projection removes that exactly; the split only decides what the stress sees.
  const bool have_before = pressure_acceleration_ &&
                           props.rho_u_before.size() == props.rho_u.size() &&
                           props.rho_w_before.size() == props.rho_w.size();
  const bool limited = pressure_acceleration_ && acceleration_limit_ > 0.0;
  const double ix = 1.0 / g.dx, iz = 1.0 / g.dz;
  // the share of grad p^n that goes through the solve on a face of density rho (rho_before at
  // the step before, when known), whose pressure difference over its spacing is dp_over_h: the
  // density ratio where the face lost mass, capped where the acceleration would pass the limit.
  // Branch-free (both candidates computed, one selected: a lane's discarded division may be
  // inf or NaN) so that the right-hand side's loop below vectorises.
  const double limit = acceleration_limit_;
  auto share = [=](double rho, double rho_before, double dp_over_h) {
    const double shrunk = have_before && rho < rho_before ? rho / rho_before : 1.0;
    const double a = std::abs(dp_over_h), capped = limit * rho / a;
    return limited && shrunk * a > limit * rho ? capped : shrunk;
  };
  auto dp_u = [&](int i, int k) { return (s.p[g.at(i, k)] - s.p[g.at(i - 1, k)]) * ix; };
  auto dp_w = [&](int i, int k) { return (s.p[g.at(i, k)] - s.p[g.at(i, k - 1)]) * iz; };
  auto before_u = [&](std::size_t c) { return have_before ? props.rho_u_before[c] : 0.0; };
  auto before_w = [&](std::size_t c) { return have_before ? props.rho_w_before[c] : 0.0; };
  const double inv_dt = 1.0 / dt;
  // The right-hand side row by row, in chunks: the faces' arithmetic in loops that vectorise,
  // then the chunk into the unknowns' column order with the initial guess.
  constexpr int kChunk = 128;
  const double ambient = rho_ambient_, gx = gx_, gz = gz_;
  const double dx = g.dx, dz = g.dz;
  auto rows = [&](int k_begin, int k_end, bool u_faces) {
    parallel_for(k_end - k_begin, true, [&](int k_offset) {
      const int k = k_begin + k_offset;
      const std::size_t row = std::size_t(k) * nx;
      const std::vector<double>& before_all = u_faces ? props.rho_u_before : props.rho_w_before;
      const std::vector<double>& force_all = u_faces ? force_u : force_w;
      const double *rho = (u_faces ? props.rho_u : props.rho_w).data() + row,
                   *v = (u_faces ? s.u : s.w).data() + row,
                   *adv = (u_faces ? adv_u : adv_w).data() + row, *p = s.p.data() + row;
      const double* rho_before = have_before ? before_all.data() + row : rho;  // (unused if not)
      const double* force = force_all.empty() ? nullptr : force_all.data() + row;
      for (int i0 = 0; i0 < nx; i0 += kChunk) {
        const int n = std::min(kChunk, nx - i0);
        std::array<double, kChunk> rhs_chunk;
        double* rhs = rhs_chunk.data();
        if (u_faces) {  // the pressure behind the face is the left cell's (column 0: nx - 1)
          auto face = [=](int i, int il) {
            const double carried = share(rho[i], rho_before[i], (p[i] - p[il]) * ix);
            rhs[i - i0] = rho[i] * V * (v[i] * inv_dt - adv[i]) + (rho[i] - ambient) * V * gx -
                          carried * dz * (p[i] - p[il]);
          };
          for_columns_with_left(nx, i0, i0 + n, [=](int il, int i) { face(i, il); });
        } else {  // the pressure behind the face is the cell below's
          const double* p_below = p - nx;
#pragma omp simd
          for (int i = i0; i < i0 + n; ++i) {
            const double carried = share(rho[i], rho_before[i], (p[i] - p_below[i]) * iz);
            rhs[i - i0] =
                rho[i] * V * (v[i] * inv_dt - adv[i] + gz) - carried * dx * (p[i] - p_below[i]);
          }
        }
        if (force)  // (added after the rest, as b_[r] += force was)
#pragma omp simd
          for (int i = i0; i < i0 + n; ++i) rhs[i - i0] += force[i];
        for (int i = i0; i < i0 + n; ++i) {
          const int r = u_faces ? op_.u_index(i, k) : op_.w_index(i, k);
          b_[r] = rhs[i - i0];
          x_[r] = v[i] + (have_increment ? guess_scale * increment_[r] : 0.0);
        }
      }
    });
  };
  rows(0, nz, true);   // u faces
  rows(1, nz, false);  // interior w faces
  // The explicit part of the linearised stress: b -= S(eta - eta_t) u^n (or the iterate `about`).
  if (tangent_) {
    as_unknowns(about ? *about : s, x_old_);
    lagged_c_.resize(props.eta_c.size());
    lagged_n_.resize(props.eta_n.size());
    const long nc = long(lagged_c_.size()), nn = long(lagged_n_.size());
    parallel_for_ranges(nc, [&](int begin, int end) {
      for (int c = begin; c < end; ++c) lagged_c_[c] = props.eta_c[c] - implicit_c_[c];
    });
    parallel_for_ranges(nn, [&](int begin, int end) {
      for (int c = begin; c < end; ++c) lagged_n_[c] = props.eta_n[c] - implicit_n_[c];
    });
    explicit_stress_.set_stress(lagged_c_, lagged_n_);
    explicit_stress_.apply(x_old_, y_);
    parallel_difference(b_, y_, b_);
  }
  // A moving bed (the co-moving frame, grid.hpp): ghost u = 2 u_bed - u, so the bed corner's
  // stress K (2/dz)(u - u_bed) has the known part -K (2/dz) u_bed, with the full eta_n (its
  // implicit and explicit parts together).
  if (g.bed_velocity() != 0.0)
    for (int i = 0; i < nx; ++i)
      b_[op_.u_index(i, 0)] += 2.0 * props.eta_n[g.at(i, 0)] * V / (g.dz * g.dz) * g.bed_velocity();
  // Known values at the top: w^n on the top face in the top cell's D_zz, and the top corner's
  // tau_xz = eta (dw/dx) (du/dz = 0 there).
  for (int i = 0; i < nx; ++i) {
    const double w_top = s.w[g.at(i, nz)];
    b_[op_.w_index(i, nz - 1)] += 2.0 * props.eta_c[g.at(i, nz - 1)] * V * iz * iz * w_top;
    const double tau = props.eta_n[g.at(i, nz)] * (w_top - s.w[g.at(i - 1, nz)]) * ix;
    b_[op_.u_index(i, nz - 1)] += g.dx * tau;
  }

  // The stopping rule (viscous_stop_tolerance) needs the change b - A u^n.
  // (u^n as unknowns: x_old_ already holds it when the stress is linearised about s)
  if (!(tangent_ && about == nullptr)) as_unknowns(s, un_);
  op_.apply(tangent_ && about == nullptr ? x_old_ : un_, y_);
  parallel_difference(b_, y_, y_);
  const double tol = viscous_stop_tolerance(tol_, std::sqrt(deterministic_dot(y_, y_)),
                                            std::sqrt(deterministic_dot(b_, b_)));
  int iterations = 0;
  if (kind_ == LinearSolverKind::LineRelaxation) {
    iterations = pcg([&](const Eigen::VectorXd& v, Eigen::VectorXd& y) { op_.apply(v, y); },
                     [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { op_.precondition(r, z); },
                     b_, x_, tol, 2000, work_);
    if (iterations < 0)
      throw std::runtime_error("viscous step: conjugate gradients did not converge");
  } else {
    op_.assemble(A_);
    solver_.set_tolerance(tol);
    iterations = solver_.solve(A_.matrix(), b_, x_);
  }
  parallel_copy(x_, increment_);
  u_star.resize(g.cells());
  w_star.assign(g.w_faces(), 0.0);
  parallel_for(nz, true, [&](int k) {
    for (int i = 0; i < nx; ++i) {
      increment_[op_.u_index(i, k)] -= s.u[g.at(i, k)];
      u_star[g.at(i, k)] = x_[op_.u_index(i, k)];
    }
  });
  parallel_for(nz - 1, true, [&](int k_from_1) {
    const int k = k_from_1 + 1;
    for (int i = 0; i < nx; ++i) increment_[op_.w_index(i, k)] -= s.w[g.at(i, k)];
  });
  dt_previous_ = dt;
  parallel_for(nz - 1, true, [&](int k_from_1) {
    const int k = k_from_1 + 1;
    for (int i = 0; i < nx; ++i) w_star[g.at(i, k)] = x_[op_.w_index(i, k)];
  });
  if (have_before || limited) {  // the rest of dt grad p^n / rho^{n+1}, where the solve took
                                 // less than the whole (see above)
    auto rest = [&share, dt](double rho, double rho_before, double dp_over_h) {
      const double carried = share(rho, rho_before, dp_over_h);
      return carried < 1.0 ? dt * (1.0 - carried) / rho * dp_over_h : 0.0;
    };
    parallel_for(nz, true, [&](int k) {
      for (int i = 0; i < nx; ++i) {
        const std::size_t c = g.at(i, k);
        u_star[c] -= rest(props.rho_u[c], before_u(c), dp_u(i, k));
      }
    });
    parallel_for(nz - 1, true, [&](int k_from_1) {
      const int k = k_from_1 + 1;
      for (int i = 0; i < nx; ++i) {
        const std::size_t c = g.at(i, k);
        w_star[c] -= rest(props.rho_w[c], before_w(c), dp_w(i, k));
      }
    });
  }
  // The top face: its own momentum balance, with the tendencies of the face below (dw/dz = 0 in
  // viscous stress, advection and gravity) but its own pressure force, from p = 0 at z = Lz:
  //   w*_top = w^n_top + (w*_below - w^n_below) + dt (a_top - a_below),  a = -grad p^n / rho.
  // The projection corrects only the increment (dp = 0 at the top), so the whole pressure is
  // tied to 0 at the lid only if the predictor carries grad p^n there. Copying w*_below instead
  // left the top cell's pressure to drift with the flow: the wave's pressure in the light fluid
  // stayed uniform up to the lid instead of falling to 0 there, and the heavier light fluid cost
  // 19 times its theory (docs/twod-validation.md §5). The hydrostatic fluid has a_top = a_below.
  for (int i = 0; i < nx; ++i) {
    const std::size_t top = g.at(i, nz), below = g.at(i, nz - 1);
    const double p_top_cell = s.p[g.at(i, nz - 1)], p_next = s.p[g.at(i, nz - 2)];
    const double accel_top = p_top_cell / (props.rho_w[top] * 0.5 * g.dz);
    const double accel_below = -(p_top_cell - p_next) / (props.rho_w[below] * g.dz);
    w_star[top] = s.w[top] + (w_star[below] - s.w[below]) + dt * (accel_top - accel_below);
  }
  return iterations;
}

}  // namespace granbench::twod

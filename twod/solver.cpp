// Time stepping of the 2D incompressible mu(I) equations (Barker & Gray 2017):
//
//   div u = 0                                                                (2.9)
//   rho (du/dt + u . grad u) = -grad p + div(2 eta D) + rho g                (2.10)
//   eta = mu(I) p / (2 |D|) in the grains, eta_l in the light fluid          (2.11)
//
// for a granular layer (rho = rho_* phi, f = 1) under a light Newtonian fluid (f = 0), with the
// interface carried by the volume fraction f. Fractional step per time level n -> n+1:
//
//   f^{n+1}          = VOF(f^n, u^n, dt)                   split PLIC, Weymouth-Yue
//   rho^{n+1}, eta   = properties(f^{n+1}, u^n, p*)        p* = p^n + hydrostatic change h^n ->
//   h^{n+1} u*               : rho^{n+1}(a0 u* - a0 u~ - a2 delta~^n)/dt = div(tau^{n+1}) - grad
//   p^n
//                                               + rho^{n+1} g,      u~ = u^n - dt A^{n+1/2}
//   dp               : div(grad dp / rho^{n+1}) = a0 div u* / dt
//   u^{n+1} = u* - (dt/a0) grad dp / rho^{n+1},   p^{n+1} = p^n + dp
//
// The non-advective part (stress, pressure, gravity) is integrated by BDF2 written on the
// increment (stress_bdf2): with the last step's increment delta^n = u^n - u~^{n-1}, carried over
// the step with the material by the momentum's own transport (delta~^n: the value at the
// departure point, as BDF2 along the flow needs; left on the grid, a face that held light fluid
// would give arriving grains the light fluid's increment), r = dt_n/dt_{n-1} and
// a0 = (1+2r)/(1+r), a2 = r^2/(1+r), the variable-step BDF2 coefficients (a0 = 1,
// a2 = 0 on the first step: backward Euler). Since a0 - (1+r) + a2 = 0, this is BDF2 for the whole
// velocity with the advection kept as the time-centred increment u~ - u^n; the recursion makes
// delta^{n+1} = dt F(t_{n+1/2}) + O(dt^3), so the step is second order. In the standard
// incremental pressure correction of Guermond, Minev & Shen (2006) the projection then takes the
// step dt/a0. Backward Euler (stress_bdf2 = false) damped the surface mode by a first-order
// error: its growth rose by 1.4 % from cfl 0.4 to 0.1 (docs/twod-validation.md §9, §10).
//
// with the advection A carried by the mass fluxes of the VOF step, rho^{n+1}(u^n - dt A) =
// rho^n u^n - dt div(G q) with time-centred face values q (momentum_advection.hpp; the option
// consistent_momentum = false advects the velocity by second-order Adams-Bashforth, A^{n+1/2} =
// (1 + r/2) A^n - (r/2) A^{n-1}, r = dt_n/dt_{n-1} of the steps actually taken), the stress
// linearised about u^n with its consistent tangent, tau^{n+1} = tau(D^n, p*) + C^n : (D* - D^n)
// (viscous_step.cpp), and p* following the surface to the new level (viscosity_pressure.cpp). These
// remove a first-order time error that the 2D growth rate is very sensitive to: the surface mode's
// growth is ~1 % of its frequency, and a phase lag of omega dt in the pressure-dependent friction
// alone cost 20 % of it at cfl 0.4 (docs/twod-validation.md).
//
// Options (parameters.hpp): the velocity form of the advection (consistent_momentum = false),
// with forward Euler (advection_ab2 = false); eta lagged at u^n
// (viscosity_tangent = false) and p^n (hydrostatic_viscosity_pressure = false); viscosity_passes >
// 1 repeats the predictor and projection with eta from the provisional u^{n+1}, p^{n+1} (Picard).
//
// Steps are CFL-limited (time_step.cpp). To land on a requested time the solver never takes a
// sliver: when the remainder is between one and two steps it takes two equal halves. (The
// projection divides by dt, so the linear solvers' residuals in a 1e-8 s step are pressure kicks.)
//
// After each step the state is checked: a NaN or a speed above velocity_limit stops the run
// with a DivergenceError naming the time, the place and the quantity.
#include "twod/solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "twod/diagnostics.hpp"
#include "twod/frame.hpp"
#include "twod/momentum_advection.hpp"
#include "twod/parallel.hpp"
#include "twod/surface_row_pressure.hpp"
#include "twod/surface_row_shear.hpp"
#include "twod/time_step.hpp"
#include "twod/viscosity_pressure.hpp"

namespace granbench::twod {

Solver::Solver(const Grid& g, const SolverParams& params, Fields initial)
    : g_(g),
      params_(params),
      model_(params.rheology),
      s_(std::move(initial)),
      props_(g),
      viscous_(g, params),
      projection_(g, params) {
  stats_.initial_volume = granular_volume(g_, s_.f);
  update_densities(g_, s_.f, params_.rheology, props_);
  effective_pressure(g_, params_, s_.p, p_eta_);
  update_viscosity(g_, s_, p_eta_, model_, props_);
}

void Solver::resume(long steps, double dt_last, double initial_volume) {
  stats_.steps = steps;
  stats_.dt_last = dt_last;
  stats_.initial_volume = initial_volume;
}

WarmStart Solver::warm_start() const {
  const Eigen::VectorXd& v = viscous_.increment();
  const Eigen::VectorXd& p = projection_.warm_start();
  WarmStart w;
  w.viscous_increment.assign(v.data(), v.data() + v.size());
  w.viscous_dt = viscous_.increment_dt();
  w.pressure_increment.assign(p.data(), p.data() + p.size());
  w.advection_u = adv_u_old_;
  w.advection_w = adv_w_old_;
  w.previous_dt = dt_previous_;
  w.increment_u = increment_u_;
  w.increment_w = increment_w_;
  w.previous_u = previous_.u;
  w.previous_w = previous_.w;
  w.dynamic_pressure = dynamic_pressure_;
  return w;
}

void Solver::set_warm_start(const WarmStart& w) {
  viscous_.set_increment(Eigen::Map<const Eigen::VectorXd>(
                             w.viscous_increment.data(), Eigen::Index(w.viscous_increment.size())),
                         w.viscous_dt);
  projection_.set_warm_start(Eigen::Map<const Eigen::VectorXd>(
      w.pressure_increment.data(), Eigen::Index(w.pressure_increment.size())));
  adv_u_old_ = w.advection_u;
  adv_w_old_ = w.advection_w;
  dt_previous_ = w.previous_dt;
  increment_u_ = w.increment_u;
  increment_w_ = w.increment_w;
  previous_.u = w.previous_u;
  previous_.w = w.previous_w;
  dynamic_pressure_ = w.dynamic_pressure;
}

double Solver::step(double dt_limit) {
  // The thread count belongs to the calling thread: set it for whichever thread steps.
  if (params_.threads >= 1 && params_.threads != thread_count()) set_thread_count(params_.threads);
  double dt_full = choose_time_step(g_, s_, params_, stats_.dt_last);
  if (stats_.dt_last <= 0.0 && params_.dt_initial > 0.0)
    dt_full = std::min(dt_full, params_.dt_initial);
  double dt = dt_full;
  if (dt_limit <= dt_full * (1.0 + 1e-9))
    dt = dt_limit;
  else if (dt_limit < 2.0 * dt_full)
    dt = 0.5 * dt_limit;  // no sliver before dt_limit: two equal steps
  const bool shortened = dt < dt_full;
  // r = dt_n / dt_{n-1} of the steps actually taken (Adams-Bashforth)
  const double r = dt_previous_ > 0.0 ? dt / dt_previous_ : 0.0;
  // 1. interface; the column heights before and after feed eta's hydrostatic pressure in step 2
  if (params_.hydrostatic_viscosity_pressure) h_before_ = surface_heights(g_, s_.f);
  const bool consistent =
      params_.consistent_momentum && params_.advect_momentum && params_.advect_interface;
  const Fields& carrier = interface_velocity(r);
  if (params_.advect_interface)
    advect_volume_fraction(g_, carrier.u, carrier.w, dt, stats_.steps % 2 == 0, s_.f, vof_,
                           vof_work_, consistent ? &grain_fluxes_ : nullptr);
  // the consistent operator needs the level-n face densities, which step 2 replaces
  if (consistent) {
    const double rho_g = params_.rheology.material.bulk_density(),
                 rho_l = params_.rheology.rho_light;
    mass_fluxes(g_, carrier, grain_fluxes_, rho_g, rho_l, dt, mass_fluxes_);
    consistent_momentum_advection(g_, s_, mass_fluxes_, props_.rho_u, props_.rho_w, dt,
                                  advection_faces_, adv_cons_u_, adv_cons_w_, carried_increment(),
                                  params_.advection_transverse_terms);
  }
  if (params_.hydrostatic_viscosity_pressure) h_after_ = surface_heights(g_, s_.f);
  // 2. properties at the new level: eta from u^n and p^n, plus the hydrostatic change of the
  //    surface's move and the dynamic pressure's extrapolated change (viscosity_pressure.cpp);
  //    the surface row's hydrostatic pressure force
  //    (surface_row_pressure.cpp)
  // (the densities p^n was balanced against, for the predictor: viscous_step.cpp)
  // update_densities overwrites every face density, so the old arrays can simply change hands
  if (props_.rho_u_before.size() == props_.rho_u.size() &&
      props_.rho_w_before.size() == props_.rho_w.size()) {
    props_.rho_u_before.swap(props_.rho_u);
    props_.rho_w_before.swap(props_.rho_w);
  } else {
    props_.rho_u_before = props_.rho_u;
    props_.rho_w_before = props_.rho_w;
  }
  update_densities(g_, s_.f, params_.rheology, props_);
  if (params_.hydrostatic_viscosity_pressure) {
    if (params_.extrapolate_dynamic_viscosity_pressure)
      viscosity_pressure(g_, params_, s_.p, h_before_, h_after_, s_.t, dt, dynamic_pressure_,
                         p_eta_);
    else
      viscosity_pressure(g_, params_, s_.p, h_before_, h_after_, p_eta_);
  } else
    effective_pressure(g_, params_, s_.p, p_eta_);
  update_viscosity(g_, s_, p_eta_, model_, props_);
  if (params_.surface_row_pressure)
    surface_row_pressure_correction(g_, params_, s_.f, force_u_);
  else
    force_u_.clear();
  if (params_.surface_row_shear)
    surface_row_shear_correction(g_, s_.f, props_, force_w_);
  else
    force_w_.clear();
  // 3. momentum predictor
  if (consistent) {
    // the one-step consistent operator, time-centred by its face values: no Adams-Bashforth
    adv_u_.swap(adv_cons_u_);
    adv_w_.swap(adv_cons_w_);
  } else if (params_.advect_momentum) {
    momentum_advection(g_, s_, advection_faces_, adv_u_, adv_w_, carried_increment());
    if (params_.advection_ab2) {
      const bool have_old = !adv_u_old_.empty() && r > 0.0;
      adv_u_old_.swap(adv_u_);  // adv_u_old_ = A^n, adv_u_ = A^{n-1}
      adv_w_old_.swap(adv_w_);
      if (!have_old) {
        adv_u_ = adv_u_old_;
        adv_w_ = adv_w_old_;
      } else {
        const long nu = long(adv_u_.size()), nw = long(adv_w_.size());
        parallel_for_ranges(nu, [&](int begin, int end) {
          for (int n = begin; n < end; ++n)
            adv_u_[n] = (1.0 + 0.5 * r) * adv_u_old_[n] - 0.5 * r * adv_u_[n];
        });
        parallel_for_ranges(nw, [&](int begin, int end) {
          for (int n = begin; n < end; ++n)
            adv_w_[n] = (1.0 + 0.5 * r) * adv_w_old_[n] - 0.5 * r * adv_w_[n];
        });
      }
    }
  } else {
    adv_u_.assign(g_.cells(), 0.0);
    adv_w_.assign(g_.w_faces(), 0.0);
  }
  // BDF2 for the non-advective part (stress_bdf2): the predictor and projection take the step
  // dt/a0 from u^n with the advection a0 A - (a2/dt) delta~^n, so that their sum is
  // u^{n+1} = u~ + (dt/a0) F^{n+1} + (a2/a0) delta~^n with u~ = u^n - dt A, and delta~^n the
  // memory carried by the advection above with the material over the step.
  const double dt_f = bdf2_rescale_advection(dt, r);
  stats_.viscous_iterations +=
      viscous_.predict(s_, props_, adv_u_, adv_w_, dt_f, u_star_, w_star_, force_u_, force_w_);
  // 4. projection
  if (params_.viscosity_passes > 1) old_ = s_;  // u^n, p^n for the further passes
  stats_.projection_iterations += projection_.project(u_star_, w_star_, props_, dt_f, s_);
  // 5. optional Picard passes: eta from the provisional u^{n+1}, p^{n+1}, then steps 3-4 again
  for (int pass = 1; pass < params_.viscosity_passes; ++pass) {
    effective_pressure(g_, params_, s_.p, p_eta_);
    update_viscosity(g_, s_, p_eta_, model_, props_);
    Fields next = old_;
    stats_.viscous_iterations += viscous_.predict(old_, props_, adv_u_, adv_w_, dt_f, u_star_,
                                                  w_star_, force_u_, force_w_, &s_);
    stats_.projection_iterations += projection_.project(u_star_, w_star_, props_, dt_f, next);
    s_.u.swap(next.u);
    s_.w.swap(next.w);
    s_.p.swap(next.p);
  }
  if (params_.stress_bdf2) record_increment();
  dt_previous_ = dt;

  s_.t += dt;
  ++stats_.steps;
  if (stats_.steps == 1 || dt < stats_.dt_min) stats_.dt_min = dt;
  if (dt > stats_.dt_max) stats_.dt_max = dt;
  if (!shortened) stats_.dt_last = dt;  // a shortened step does not throttle the next one
  check_health();
  return dt;
}

const Fields& Solver::interface_velocity(double r) {
  if (!params_.interface_midstep_velocity) return s_;
  const bool have_previous = r > 0.0 && previous_.u.size() == s_.u.size();
  if (have_previous) {
    midstep_.u.resize(s_.u.size());
    midstep_.w.resize(s_.w.size());
    const long nu = long(s_.u.size()), nw = long(s_.w.size());
    const double c = 0.5 * r;
    parallel_for_ranges(nu, [&](int begin, int end) {
      for (int n = begin; n < end; ++n) midstep_.u[n] = s_.u[n] + c * (s_.u[n] - previous_.u[n]);
    });
    parallel_for_ranges(nw, [&](int begin, int end) {
      for (int n = begin; n < end; ++n) midstep_.w[n] = s_.w[n] + c * (s_.w[n] - previous_.w[n]);
    });
  }
  parallel_copy(s_.u, previous_.u);
  parallel_copy(s_.w, previous_.w);
  return have_previous ? midstep_ : s_;
}

CarriedField Solver::carried_increment() {
  if (!params_.stress_bdf2 || increment_u_.empty() || !params_.advect_momentum) return {};
  return {&increment_u_, &increment_w_, &transport_u_, &transport_w_};
}

double Solver::bdf2_rescale_advection(double dt, double r) {
  if (!params_.stress_bdf2) return dt;
  const long nu = long(adv_u_.size()), nw = long(adv_w_.size());
  advected_u_.resize(std::size_t(nu));
  advected_w_.resize(std::size_t(nw));
  // The first step, or a restart without the memory: backward Euler (a0 = 1, a2 = 0), and only
  // the advected velocity u~ = u^n - dt A (whatever the step's advection; zero without it).
  if (r <= 0.0 || increment_u_.size() != adv_u_.size() || increment_w_.size() != adv_w_.size()) {
    parallel_for_ranges(nu, [&](int begin, int end) {
      for (int n = begin; n < end; ++n) advected_u_[n] = s_.u[n] - dt * adv_u_[n];
    });
    parallel_for_ranges(nw, [&](int begin, int end) {
      for (int n = begin; n < end; ++n) advected_w_[n] = s_.w[n] - dt * adv_w_[n];
    });
    return dt;
  }
  const double a0 = (1.0 + 2.0 * r) / (1.0 + r), a2 = r * r / (1.0 + r), c = a2 / dt;
  // u~, the carried memory delta~ = delta - dt (its transport term) when the advection carried
  // it, and a0 A - c delta~, in one pass over each array
  auto fold = [&](std::vector<double>& adv, const std::vector<double>& vel,
                  const std::vector<double>& increment, const std::vector<double>& transport,
                  std::vector<double>& advected, bool carried) {
    const long size = long(adv.size());
    if (carried) {
      parallel_for_ranges(size, [&](int begin, int end) {
        for (int n = begin; n < end; ++n) {
          const double a = adv[n];
          advected[n] = vel[n] - dt * a;
          adv[n] = a0 * a - c * (increment[n] - dt * transport[n]);
        }
      });
    } else {
      parallel_for_ranges(size, [&](int begin, int end) {
        for (int n = begin; n < end; ++n) {
          const double a = adv[n];
          advected[n] = vel[n] - dt * a;
          adv[n] = a0 * a - c * increment[n];
        }
      });
    }
  };
  const bool carried = carried_increment().u != nullptr;
  fold(adv_u_, s_.u, increment_u_, transport_u_, advected_u_, carried);
  fold(adv_w_, s_.w, increment_w_, transport_w_, advected_w_, carried);
  return dt / a0;
}

void Solver::record_increment() {
  const long nu = long(advected_u_.size()), nw = long(advected_w_.size());
  increment_u_.resize(std::size_t(nu));
  increment_w_.resize(std::size_t(nw));
  parallel_for_ranges(nu, [&](int begin, int end) {
    for (int n = begin; n < end; ++n) increment_u_[n] = s_.u[n] - advected_u_[n];
  });
  parallel_for_ranges(nw, [&](int begin, int end) {
    for (int n = begin; n < end; ++n) increment_w_[n] = s_.w[n] - advected_w_[n];
  });
}

void Solver::advance_to(double t_end) {
  while (s_.t < t_end * (1.0 - 1e-14)) step(t_end - s_.t);
}

RunStatistics Solver::statistics() const {
  RunStatistics r = stats_;
  r.volume = granular_volume(g_, s_.f);
  r.clipped_volume = vof_.clipped_volume * g_.cell_volume();
  r.vof_substepped_steps = vof_.substepped_steps;
  r.factorisations = viscous_.stats().factorisations + projection_.stats().factorisations;
  double div = 0.0;
  for (int k = 0; k < g_.nz; ++k)
    for (int i = 0; i < g_.nx; ++i)
      div = std::max(div, std::abs(cell_divergence(g_, s_.u, s_.w, i, k)));
  r.max_divergence = div;
  return r;
}

void Solver::check_health() const {
  // Find whether any row holds a bad value in parallel (a flag per row, so the result does not
  // depend on the thread count); only then search it serially, to report the first one.
  auto bad = [&](std::size_t c, double w) {
    return !std::isfinite(s_.u[c]) || std::abs(s_.u[c]) > params_.velocity_limit ||
           !std::isfinite(w) || std::abs(w) > params_.velocity_limit || !std::isfinite(s_.p[c]) ||
           !std::isfinite(s_.f[c]);
  };
  std::vector<char>& row_is_bad = bad_row_flags_;
  row_is_bad.assign(std::size_t(g_.nz), 0);
  parallel_for(g_.nz, true, [&](int k) {
    for (int i = 0; i < g_.nx; ++i)
      if (bad(g_.at(i, k), s_.w[g_.at(i, k + 1)])) {
        row_is_bad[k] = 1;
        break;
      }
  });
  if (std::find(row_is_bad.begin(), row_is_bad.end(), 1) == row_is_bad.end()) return;
  auto fail = [&](const char* what, double value, double x_grid, double z) {
    const double x = lab_position(g_, x_grid, s_.t);  // (frame.hpp)
    std::ostringstream m;
    m << "diverged at t = " << s_.t << " s: " << what << " = " << value << " at x = " << x
      << " m, z = " << z << " m (step " << stats_.steps << ")";
    throw DivergenceError(m.str(), s_.t, x, z);
  };
  for (int k = 0; k < g_.nz; ++k)
    for (int i = 0; i < g_.nx; ++i) {
      const std::size_t c = g_.at(i, k);
      const double u = s_.u[c], w = s_.w[g_.at(i, k + 1)];
      if (!std::isfinite(u) || std::abs(u) > params_.velocity_limit)
        fail("u", u + g_.frame_speed, i * g_.dx, g_.zc(k));  // lab-frame u
      if (!std::isfinite(w) || std::abs(w) > params_.velocity_limit)
        fail("w", w, g_.xc(i), (k + 1) * g_.dz);
      if (!std::isfinite(s_.p[c])) fail("p", s_.p[c], g_.xc(i), g_.zc(k));
      if (!std::isfinite(s_.f[c])) fail("f", s_.f[c], g_.xc(i), g_.zc(k));
    }
}

}  // namespace granbench::twod

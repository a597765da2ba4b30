// The 2D two-phase incompressible mu(I) solver: one time step is
//   1. VOF advection of f by u^n                               (vof_advection.cpp)
//   2. densities and viscosities at the new level              (properties.cpp)
//   3. explicit advection, implicit viscous predictor          (momentum_advection, viscous_step)
//   4. variable-density projection                             (projection.cpp)
// with a CFL-limited step (time_step.cpp). See solver.cpp for the equations.
#pragma once

#include <stdexcept>
#include <string>

#include "twod/fields.hpp"
#include "twod/grid.hpp"
#include "twod/momentum_advection.hpp"
#include "twod/parameters.hpp"
#include "twod/projection.hpp"
#include "twod/properties.hpp"
#include "twod/viscosity_pressure.hpp"
#include "twod/viscous_step.hpp"
#include "twod/vof_advection.hpp"

namespace granbench::twod {

// A diverged run: what, where and when.
struct DivergenceError : std::runtime_error {
  DivergenceError(const std::string& what, double t_, double x_, double z_)
      : std::runtime_error(what), t(t_), x(x_), z(z_) {}
  double t, x, z;
};

// What the solver carries from one step to the next besides the state: the initial guesses of
// its linear solves. Saved in checkpoints so that a restarted run repeats the uninterrupted one
// exactly.
struct WarmStart {
  std::vector<double> viscous_increment;   // u* - u^n of the last predictor (solver unknowns)
  double viscous_dt = 0.0;                 // the step of that predictor
  std::vector<double> pressure_increment;  // the last projection's delta p
  // The second-order step's memory: A^n (Adams-Bashforth) and the last step taken.
  std::vector<double> advection_u, advection_w;
  double previous_dt = 0.0;
  // The BDF2 step's memory (stress_bdf2): the last step's non-advective velocity increment.
  std::vector<double> increment_u, increment_w;
  // u^{n-1} (interface_midstep_velocity)
  std::vector<double> previous_u, previous_w;
  // The dynamic pressure of the last two levels (extrapolate_dynamic_viscosity_pressure)
  DynamicPressureHistory dynamic_pressure;
};

struct RunStatistics {
  long steps = 0;
  long viscous_iterations = 0, projection_iterations = 0;
  long factorisations = 0;
  double initial_volume = 0.0;    // granular volume at the start [m^2 per unit width]
  double volume = 0.0;            // now
  double clipped_volume = 0.0;    // volume touched by clipping f to [0, 1]
  long vof_substepped_steps = 0;  // steps whose interface moved in sub-steps (vof_advection.hpp)
  double dt_min = 0.0, dt_max = 0.0, dt_last = 0.0;
  double max_divergence = 0.0;  // max |div u| after the last projection [1/s]
  double mass_error() const {
    return initial_volume > 0.0 ? (volume - initial_volume) / initial_volume : 0.0;
  }
};

class Solver {
 public:
  Solver(const Grid& g, const SolverParams& params, Fields initial);
  // Advance one step of at most dt_limit; returns the step taken. Throws DivergenceError.
  double step(double dt_limit);
  // Step until time t_end (exactly).
  void advance_to(double t_end);

  const Grid& grid() const { return g_; }
  const Fields& state() const { return s_; }
  Fields& mutable_state() { return s_; }
  const Properties& properties() const { return props_; }
  const SolverParams& params() const { return params_; }
  // Change the thread count from the next step on (results do not depend on it).
  void set_threads(int n) { params_.threads = n; }
  const ViscosityModel& viscosity_model() const { return model_; }
  RunStatistics statistics() const;
  // Restore counters and the step size after a restart.
  void resume(long steps, double dt_last, double initial_volume);
  WarmStart warm_start() const;
  void set_warm_start(const WarmStart& w);

 private:
  void check_health() const;
  // The velocity that moves the interface this step (interface_midstep_velocity): u^n, or its
  // mid-step extrapolation from u^n and u^{n-1}; keeps u^n for the next step.
  const Fields& interface_velocity(double r);
  // stress_bdf2: delta^n for the advection to carry with the material over this step (the
  // departure points of the BDF2 step along the flow; none before the first step). Its
  // transport term lands in transport_u_, transport_w_.
  CarriedField carried_increment();
  // stress_bdf2: keep u~ = u^n - dt A, move the carried memory and fold a0, a2 into the
  // advection; returns dt/a0, the step the predictor and the projection take (dt itself with
  // backward Euler).
  double bdf2_rescale_advection(double dt, double r);
  // stress_bdf2: delta^{n+1} = u^{n+1} - u~ for the next step.
  void record_increment();

  Grid g_;
  SolverParams params_;
  ViscosityModel model_;
  Fields s_;
  Properties props_;
  ViscousStep viscous_;
  Projection projection_;
  VofStats vof_;
  VofWorkspace vof_work_;
  Fields old_;  // u^n, p^n kept for the Picard passes (viscosity_passes > 1)
  std::vector<double> adv_u_, adv_w_, u_star_, w_star_;
  GrainFluxes grain_fluxes_;                     // the VOF step's fluxes (consistent_momentum)
  MassFluxes mass_fluxes_;                       // and the mass they carry
  AdvectionFaces advection_faces_;               // scratch of the momentum advection
  std::vector<double> adv_cons_u_, adv_cons_w_;  // the consistent operator at level n
  std::vector<double> adv_u_old_, adv_w_old_;    // A^n kept for the next step (advection_ab2)
  std::vector<double> h_before_, h_after_;       // column heights before and after the VOF step
  std::vector<double> p_eta_;  // the pressure eta is evaluated at (viscosity_pressure.hpp)
  DynamicPressureHistory dynamic_pressure_;  // extrapolate_dynamic_viscosity_pressure
  std::vector<double> force_u_;              // surface-row pressure correction per u-face
  std::vector<double> force_w_;              // surface-row shear correction per w-face
  double dt_previous_ = 0.0;                 // the last step taken (shortened or not)
  // stress_bdf2: the advected velocity u~ of this step, and delta^n = u^n - u~^{n-1}, the last
  // step's non-advective increment (empty before the first step)
  std::vector<double> advected_u_, advected_w_, increment_u_, increment_w_;
  std::vector<double> transport_u_, transport_w_;  // scratch: the transport of delta^n
  Fields previous_, midstep_;  // u^{n-1} and the mid-step velocity (interface_midstep_velocity)
  mutable std::vector<char> bad_row_flags_;  // scratch of check_health: a flag per row
  RunStatistics stats_;
};

}  // namespace granbench::twod

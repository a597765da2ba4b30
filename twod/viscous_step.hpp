// The implicit momentum predictor (viscous_step.cpp).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "twod/fields.hpp"
#include "twod/grid.hpp"
#include "twod/parameters.hpp"
#include "twod/spd_solver.hpp"
#include "twod/viscous_operator.hpp"

namespace granbench::twod {

// The relative residual ||b - A u*|| / ||b|| at which the predictor's solve stops, for the
// SolverParams::viscous_tolerance `tolerance`, the change ||b - A u^n|| and ||b||: tolerance
// times the change, but never looser than 1e-8 ||b|| nor tighter than 1e-12 ||b||.
double viscous_stop_tolerance(double tolerance, double change, double b_norm);

class ViscousStep {
 public:
  ViscousStep(const Grid& g, const SolverParams& params);
  // Predict (u*, w*) from the state s (u^n, w^n, p^n), the explicit advection adv_u, adv_w and
  // the properties at the new time level. Returns the solver iterations.
  // force_u, force_w (may be empty): explicit forces per u-face and per w-face [N per unit
  // width], added to the right-hand side. about: the velocity the stress is linearised about
  // (viscosity_tangent); s when null, the provisional new level in further Picard passes.
  int predict(const Fields& s, const Properties& props, const std::vector<double>& adv_u,
              const std::vector<double>& adv_w, double dt, std::vector<double>& u_star,
              std::vector<double>& w_star, const std::vector<double>& force_u = {},
              const std::vector<double>& force_w = {}, const Fields* about = nullptr);
  const SolveStats& stats() const { return solver_.stats(); }
  // The last predictor increment u* - u^n and its step: the next initial guess is
  // u^n + (dt / dt_previous) increment. Kept in checkpoints so that a restart is exact.
  const Eigen::VectorXd& increment() const { return increment_; }
  double increment_dt() const { return dt_previous_; }
  void set_increment(Eigen::VectorXd increment, double dt) {
    increment_ = std::move(increment);
    dt_previous_ = dt;
  }

 private:
  // The velocity of f (u-faces, interior w-faces) in the solve's ordering of unknowns.
  void as_unknowns(const Fields& f, Eigen::VectorXd& v) const;

  Grid g_;
  double gx_, gz_;      // gravity components g sin(zeta), -g cos(zeta)
  double rho_ambient_;  // density whose weight along x the ambient pressure gradient carries
  LinearSolverKind kind_;
  double tol_;
  bool tangent_;                // SolverParams::viscosity_tangent
  bool pressure_acceleration_;  // SolverParams::predictor_pressure_acceleration
  double acceleration_limit_;   // SolverParams::predictor_acceleration_limit times g [m/s^2]
  ViscousOperator op_;
  ViscousOperator explicit_stress_;  // S(eta - eta_tangent), applied to u^n (tangent_ only)
  PatternedMatrix A_;                // assembled only for the sparse-matrix preconditioners
  SpdSolver solver_;
  PcgWorkspace work_;                            // conjugate-gradient vectors, reused across steps
  Eigen::VectorXd b_, x_, x_old_, y_, un_;       // x_old_: the linearisation's u; un_: u^n
  std::vector<double> lagged_c_, lagged_n_;      // eta - eta_m at cells and corners
  std::vector<double> implicit_c_, implicit_n_;  // eta_m: the implicit part of the stress
  Eigen::VectorXd increment_;  // u* - u^n of the last predict (empty before the first)
  double dt_previous_ = 0.0;
};

}  // namespace granbench::twod

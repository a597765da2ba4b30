// The implicit momentum predictor (viscous_step.cpp).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "fields.hpp"
#include "grid.hpp"
#include "parameters.hpp"
#include "spd_solver.hpp"

namespace granbench::twod {

class ViscousStep {
 public:
  ViscousStep(const Grid& g, const SolverParams& params);
  // Predict (u*, w*) from the state s (u^n, w^n, p^n), the explicit advection adv_u, adv_w and
  // the properties at the new time level. Returns the solver iterations.
  int predict(const Fields& s, const Properties& props, const std::vector<double>& adv_u,
              const std::vector<double>& adv_w, double dt, std::vector<double>& u_star,
              std::vector<double>& w_star);
  const SolveStats& stats() const { return solver_.stats(); }

 private:
  Grid g_;
  double gx_, gz_;  // gravity components g sin(zeta), -g cos(zeta)
  PatternedMatrix A_;
  SpdSolver solver_;
  Eigen::VectorXd b_, x_;
};

}  // namespace granbench::twod

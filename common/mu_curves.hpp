// Friction curves mu(I) for the incompressible mu(I)-rheology (Barker & Gray 2017):
//
//   Jop            mu_J = mu_s + (mu_d - mu_s)/(I0/I + 1)                                 (2.12)
//   low-I          sqrt(alpha/ln(A_-/I)) for I <= I1N (of mu_J), mu_J above;   (5.2)-(5.3)
//   regularised    sqrt(alpha/ln(A_-/I)) for I <= I1N, (mu_s I0 + mu_d I + mu_inf I^2)/(I0 + I)
//                  above, I1N the lower neutral point of that upper branch     (6.3)-(6.4)
//   Kamrin-Koval   mu_s + b I + (mu_0 - mu_s) exp(-I/c_K),  b = (mu_d - mu_s)/I0          (5.1)
//   Holyoake       (mu_s I0 + mu_d I + c (h0/d)^(-1/3) I^2)/(I0 + I)                       (6.1)
//
// Each curve gives its value, analytic derivative dmu/dI and the inverse I(mu) (GSL Brent root
// finding on a bracket). MuCurve is a small value type: construct once, copy freely.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "common/material.hpp"

namespace granbench {

enum class CurveKind { Jop, Regularised, LowI, KamrinKoval, Holyoake };

// Names as used on the command line: jop, regularised, low-i, kamrin-koval, holyoake.
std::string_view curve_name(CurveKind kind);
// Throws std::invalid_argument for an unknown name.
CurveKind parse_curve_name(std::string_view name);
std::vector<std::string> all_curve_names();

// Thrown when mu lies outside the values a curve takes (e.g. a slope with no steady flow).
struct CurveRangeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class MuCurve {
 public:
  // h0 is the flow depth, used only by the Holyoake curve (6.1).
  MuCurve(CurveKind kind, const Material& material, double h0 = 4e-3);

  double mu(double I) const;
  // mu at every I of a range (mu.size() == I.size()): one call per right-hand side of a model,
  // not one per cell.
  void mu_many(std::span<const double> I, std::span<double> mu) const;
  double dmu_dI(double I) const;
  // mu and its logarithmic slope (I / mu) dmu/dI = d ln mu / d ln I (Gamma / mu of the tangent
  // viscosity) at one I > 0, in one evaluation with fewer divisions than mu() and dmu_dI()
  // apart: what the 2D model needs at every cell and corner of every step.
  struct WithLogSlope {
    double mu;
    double log_slope;
  };
  WithLogSlope mu_with_log_slope(double I) const;
  // The same at every I of a range (all three spans of one size), each value bitwise that of
  // mu_with_log_slope: the rational upper branch of all I in one vectorised loop, then the few I
  // on the low-I branch (or <= 0) one by one. Any I may be +inf or NaN (its values are then
  // whatever the arithmetic gives): the 2D model evaluates whole rows and discards the lanes it
  // does not use.
  void mu_with_log_slope_many(std::span<const double> I, std::span<double> mu,
                              std::span<double> log_slope) const;
  // I with mu(I) = target; throws CurveRangeError outside (mu_min, mu_max).
  double inverse(double target_mu) const;

  CurveKind kind() const { return kind_; }
  const Material& material() const { return material_; }
  // Infimum and supremum of mu over I in (0, inf) for the monotone curves.
  double mu_min() const { return mu_min_; }
  double mu_max() const { return mu_max_; }
  // Junction of the low-I branch (regularised and low-I curves), and its A_- of (5.3)/(6.4).
  double junction_I() const { return junction_I_; }
  double A_minus() const { return A_minus_; }
  // Coefficient of I^2 in the upper branch numerator: mu_inf (regularised), c(h0/d)^(-1/3)
  // (Holyoake), 0 otherwise.
  double quadratic_coefficient() const { return quad_; }

 private:
  double upper_branch(double I) const;  // the intermediate/high-I expression
  double upper_branch_derivative(double I) const;

  CurveKind kind_;
  Material material_;
  double quad_ = 0.0;
  double junction_I_ = 0.0;
  double A_minus_ = 0.0;
  double mu_min_ = 0.0;
  double mu_max_ = 0.0;
};

}  // namespace granbench

// A 2D linear eigenmode in physical units, evaluated anywhere in the layer: the perturbation that
// seeds a 2D run with one clean mode, and the profiles written to output.
//
// With surface h(x, t) = h0 + Re(a exp(i k x + lambda t)) (a real: h = h0 + a cos(k x) at t = 0),
// the fields are u = U0(z) + Re(a u_hat(z) e^{ikx}), w = Re(a w_hat(z) e^{ikx}),
// p = p0(z) + Re(a p_hat(z) e^{ikx}), where U0, p0 are (5.5), (5.4) and u_hat, w_hat, p_hat are the
// eigenfunctions per metre of surface displacement (u_hat, w_hat in s^-1, p_hat in Pa m^-1).
// Between h0 and h(x) the perturbation is continued with its value at z = h0 (the linear
// solution is only defined to O(a) there) and p is clipped at zero; p_hat(h0) = rho g cos(zeta)
// so that the total pressure vanishes at the perturbed surface to O(a).
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "analysis/linear2d/base_state.hpp"
#include "analysis/linear2d/chebyshev.hpp"
#include "analysis/linear2d/linear_stability_2d.hpp"
#include "analysis/linear2d/operator.hpp"
#include "analysis/linear2d/spectrum.hpp"
#include "common/steady_state.hpp"

namespace granbench::linear2d {

class Eigenmode {
 public:
  // `pair` is an eigenpair of assemble_pencil(b, k_hat, grid, map); b is the base state of s.
  Eigenmode(const SteadyState& s, const LinearBaseState& b, double k_hat, const ChebyshevGrid& grid,
            VerticalMap map, const Eigenpair& pair);

  double k() const { return k_; }                          // [1/m]
  std::complex<double> lambda() const { return lambda_; }  // [1/s]
  double growth_rate() const { return lambda_.real(); }
  double phase_speed() const { return -lambda_.imag() / k_; }

  // Complex amplitudes per metre of surface displacement at height z in [0, h0].
  std::complex<double> u_hat(double z) const;
  std::complex<double> w_hat(double z) const;
  std::complex<double> p_hat(double z) const;

  // Nodal profiles (z ascending from the bed): for output and plots.
  const std::vector<double>& z_nodes() const { return z_; }
  const Eigen::VectorXcd& u_nodes() const { return u_; }
  const Eigen::VectorXcd& w_nodes() const { return w_; }
  const Eigen::VectorXcd& p_nodes() const { return p_; }

  struct Fields {
    double u = 0.0, w = 0.0, p = 0.0;
    bool granular = false;  // z <= h(x)
  };
  double height(double x, double a) const;                  // h0 + a cos(k x)
  Fields perturbation(double x, double z, double a) const;  // O(a) parts only
  Fields seeded_state(double x, double z, double a) const;  // base state + perturbation

 private:
  std::complex<double> at(const Eigen::VectorXcd& f, double z) const;

  SteadyState steady_;
  ChebyshevGrid grid_;
  VerticalMap map_;
  double k_ = 0.0;
  std::complex<double> lambda_;
  std::vector<double> z_;
  Eigen::VectorXcd u_, w_, p_;  // in node order of the grid (bed first), SI per metre of h
};

// One call for seeding: the surface eigenmode of the Bagnold state of `curve` at wavelength Lx
// (the mode linear_stability_2d with opt reports, computed alone; opt.N_check and
// opt.light_layer are not used).
Eigenmode surface_eigenmode(const SteadyState& s, const MuCurve& curve, double Lx,
                            const Linear2DOptions& opt = {});

}  // namespace granbench::linear2d

// Eigenmode fields in physical units from a scaled eigenvector (analysis/linear2d/eigenmode.hpp).
// The eigenvector is normalised by its surface displacement; velocities scale with u_bar_0/h0 per
// unit h/h0, pressure with rho_* phi g cos(zeta) (7.13). The pressure is recovered from the normal
// stress unknown N = p - tau_zz with tau_zz = -2 eta_n i k u.
#include "analysis/linear2d/eigenmode.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granbench::linear2d {

Eigenmode::Eigenmode(const SteadyState& s, const LinearBaseState& b, double k_hat,
                     const ChebyshevGrid& grid, VerticalMap map, const Eigenpair& pair)
    : steady_(s), grid_(grid), map_(map), k_(k_hat / s.h0), lambda_(pair.lambda * s.u_mean / s.h0) {
  const int n = grid.nodes();
  if (pair.v.size() != 4 * n + 1) throw std::invalid_argument("eigenvector does not fit the grid");
  const std::complex<double> H = pair.v(4 * n);
  if (std::abs(H) == 0.0) throw std::invalid_argument("eigenmode has no surface displacement");
  const double vel = s.u_mean / s.h0;  // per metre of h
  const double pres = s.material.bulk_density() * s.material.g * std::cos(s.zeta);
  const std::complex<double> ik(0.0, k_hat);
  const int m = map == VerticalMap::SquareRoot ? 2 : 1;
  u_.resize(n);
  w_.resize(n);
  p_.resize(n);
  z_.resize(n);
  for (int j = 0; j < n; ++j) {
    const double sj = grid.s()(j);
    const std::complex<double> u = pair.v(j) / H, w = pair.v(n + j) / H;
    const std::complex<double> N = pair.v(2 * n + j) / H;
    const double eta_n = b.eta_n0 * std::pow(sj, m * b.beta);
    u_(j) = vel * u;
    w_(j) = vel * w;
    p_(j) = pres * (N - 2.0 * eta_n * ik * u);
    z_[j] = s.h0 * map_height(map, sj);
  }
}

std::complex<double> Eigenmode::at(const Eigen::VectorXcd& f, double z) const {
  const double zc = std::clamp(z, 0.0, steady_.h0);
  return grid_.interpolate(f, map_coordinate(map_, zc / steady_.h0));
}

std::complex<double> Eigenmode::u_hat(double z) const {
  return at(u_, z);
}
std::complex<double> Eigenmode::w_hat(double z) const {
  return at(w_, z);
}
std::complex<double> Eigenmode::p_hat(double z) const {
  return at(p_, z);
}

double Eigenmode::height(double x, double a) const {
  return steady_.h0 + a * std::cos(k_ * x);
}

Eigenmode::Fields Eigenmode::perturbation(double x, double z, double a) const {
  Fields f;
  f.granular = z <= height(x, a);
  if (!f.granular) return f;
  const std::complex<double> phase = std::polar(a, k_ * x);
  f.u = (phase * u_hat(z)).real();
  f.w = (phase * w_hat(z)).real();
  f.p = (phase * p_hat(z)).real();
  return f;
}

Eigenmode::Fields Eigenmode::seeded_state(double x, double z, double a) const {
  Fields f = perturbation(x, z, a);
  if (!f.granular) return f;
  const double rho_g_cos =
      steady_.material.bulk_density() * steady_.material.g * std::cos(steady_.zeta);
  f.u += steady_.velocity(std::min(z, steady_.h0));         // (5.5)
  f.p = std::max(0.0, f.p + rho_g_cos * (steady_.h0 - z));  // (5.4), continued to h(x)
  return f;
}

Eigenmode surface_eigenmode(const SteadyState& s, const MuCurve& curve, double Lx,
                            const Linear2DOptions& opt) {
  // The surface mode alone: the seed needs neither the other modes nor the convergence check.
  const double k_hat = scaled_wavenumber(s, Lx);
  const LinearBaseState b = mu_i_base_state(s, curve);
  return Eigenmode(s, b, k_hat, ChebyshevGrid(opt.N), opt.map,
                   surface_mode(b, k_hat, opt.N, opt.map, opt.path));
}

}  // namespace granbench::linear2d

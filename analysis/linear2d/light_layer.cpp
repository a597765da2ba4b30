// Grains under a light Newtonian fluid: base state, collocation pencil and the continuation from
// the stress-free surface. The equations are in analysis/linear2d/light_layer.hpp.
#include "analysis/linear2d/light_layer.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "analysis/linear2d/spectrum.hpp"

namespace granbench::linear2d {

LightLayerScaled scale(const LightLayer& layer, const SteadyState& s) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("light layer: " + what);
  };
  require(layer.rho_l > 0.0 && std::isfinite(layer.rho_l), "rho_l must be > 0");
  require(layer.eta_l > 0.0 && std::isfinite(layer.eta_l), "eta_l must be > 0");
  require(layer.Lz_over_h0 > 1.0 && std::isfinite(layer.Lz_over_h0), "Lz/h0 must be > 1");
  const double rho_g = s.material.rho_star * s.material.phi;
  const double stress = rho_g * s.material.g * std::cos(s.zeta) * s.h0;  // (7.13) stress scale
  LightLayerScaled l;
  l.r = layer.rho_l / rho_g;
  l.eps = layer.eta_l * (s.u_mean / s.h0) / stress;  // viscous stress of the rate u_bar_0/h0
  l.ell = layer.Lz_over_h0 - 1.0;
  return l;
}

double LightBaseFlow::U(double z) const {
  const double y = z - 1.0;
  return U_interface + (mu / nu) * (ell * y - 0.5 * y * y);  // eps U'' = -r mu, U'(1 + ell) = 0
}

double LightBaseFlow::dU(double z) const {
  return (mu / nu) * (ell - (z - 1.0));
}

LightBaseFlow light_base_flow(const LinearBaseState& g, const LightLayerScaled& l) {
  return {g.U_surface(), g.mu, l.nu(), l.ell};
}

LinearBaseState with_overburden(LinearBaseState stress_free, const LightLayerScaled& l) {
  stress_free.overburden = l.overburden();  // the column's weight r ell on the grains
  return stress_free;
}

LightLayerOffsets light_layer_offsets(int N, int M) {
  const int start = 4 * (N + 1) + 1, m = M + 1;
  return {start, start + m, start + 2 * m, start + 3 * m};
}

Pencil assemble_light_layer_pencil(const LinearBaseState& g, const LightLayerScaled& l,
                                   double k_hat, const ChebyshevGrid& grains,
                                   const ChebyshevGrid& fluid) {
  using cd = std::complex<double>;
  if (std::abs(g.overburden - l.overburden()) > 1e-14 * (1.0 + l.overburden()))
    throw std::invalid_argument("light layer: the granular state must carry the overburden");
  const Pencil Pg = assemble_pencil(g, k_hat, grains, VerticalMap::SquareRoot);
  const int N = grains.intervals(), M = fluid.intervals(), m = M + 1;
  const int ng = int(Pg.A.rows()), dim = ng + 4 * m;
  Pencil P;
  P.N = N;
  P.map = VerticalMap::SquareRoot;
  P.A = Eigen::MatrixXcd::Zero(dim, dim);
  P.B = Eigen::MatrixXcd::Zero(dim, dim);
  P.A.topLeftCorner(ng, ng) = Pg.A;
  P.B.topLeftCorner(ng, ng) = Pg.B;

  const LightBaseFlow base = light_base_flow(g, l);
  const LightLayerOffsets o = light_layer_offsets(N, M);
  const Eigen::MatrixXd& D = fluid.D();  // d/dsigma, z = 1 + ell sigma
  const cd ik(0.0, k_hat);
  const double k2 = k_hat * k_hat, F2 = g.F * g.F, nu = l.nu(), ell = l.ell;

  // Each equation multiplied by dz/dsigma = ell.
  for (int j = 0; j < m; ++j) {
    const double z = 1.0 + ell * fluid.s()(j);
    const double U = base.U(z), dU = base.dU(z);
    // Strain rate: Du + i k w - T = 0
    P.A.block(o.u + j, o.u, 1, m) = D.row(j).cast<cd>();
    P.A(o.u + j, o.w + j) = ell * ik;
    P.A(o.u + j, o.T + j) = -ell;
    // Mass: Dw + i k u = 0
    P.A.block(o.w + j, o.w, 1, m) = D.row(j).cast<cd>();
    P.A(o.w + j, o.u + j) = ell * ik;
    // x momentum: nu DT - F^2 ((lambda + i k U) u + U' w) - i k N - 4 nu k^2 u = 0
    P.A.block(o.T + j, o.T, 1, m) = (nu * D.row(j)).cast<cd>();
    P.A(o.T + j, o.u + j) = -ell * (F2 * ik * U + 4.0 * nu * k2);
    P.A(o.T + j, o.w + j) = -ell * F2 * dU;
    P.A(o.T + j, o.N + j) = -ell * ik;
    P.B(o.T + j, o.u + j) = ell * F2;
    // z momentum: DN - i k nu T + F^2 (lambda + i k U) w = 0
    P.A.block(o.N + j, o.N, 1, m) = D.row(j).cast<cd>();
    P.A(o.N + j, o.T + j) = -ell * ik * nu;
    P.A(o.N + j, o.w + j) = ell * F2 * ik * U;
    P.B(o.N + j, o.w + j) = -ell * F2;
  }

  auto replace_row = [&](int row) {
    P.A.row(row).setZero();
    P.B.row(row).setZero();
  };
  const int top = 0, interface = M, surface = N;  // fluid node M and granular node N: z = 1
  // Continuity of velocity at z = 1 + h: u_l - u_g - h (U0'(1) - U_l'(1)) = 0, w_l - w_g = 0.
  replace_row(o.u + interface);
  P.A(o.u + interface, o.u + interface) = 1.0;
  P.A(o.u + interface, Pg.u() + surface) = -1.0;
  P.A(o.u + interface, Pg.h()) = -(g.dU0(1.0) - base.dU(1.0));
  replace_row(o.w + interface);
  P.A(o.w + interface, o.w + interface) = 1.0;
  P.A(o.w + interface, Pg.w() + surface) = -1.0;
  // Top: du/dz = 0 (T = i k w) and p = 0 (N - 2 i k nu u = 0).
  replace_row(o.T + top);
  P.A(o.T + top, o.T + top) = 1.0;
  P.A(o.T + top, o.w + top) = -ik;
  replace_row(o.N + top);
  P.A(o.N + top, o.N + top) = 1.0;
  P.A(o.N + top, o.u + top) = -2.0 * ik * nu;
  // The granular surface rows were T_g - mu h = 0 and N_g - h = 0 (stress-free); the fluid's
  // stresses and hydrostatic jumps enter: T_g - mu (1 - r) h - eps T = 0, N_g - (1 - r) h - r N =
  // 0.
  const int rowT = Pg.shear() + surface, rowN = Pg.normal() + surface;
  P.A(rowT, Pg.h()) = -g.mu * (1.0 - l.r);
  P.A(rowT, o.T + interface) = -l.eps;
  P.A(rowN, Pg.h()) = -(1.0 - l.r);
  P.A(rowN, o.N + interface) = -l.r;
  return P;
}

namespace {
// Shift between the surface velocity and the kinematic speed, as for the stress-free spectrum.
std::complex<double> spectrum_shift(const LinearBaseState& g, double k_hat) {
  return {0.05, -0.5 * (2.5 + g.U_surface()) * k_hat - 0.0137};
}

// The eigenvalue of P nearest to `target`: the largest 1/(lambda - sigma) of the shift-and-invert
// operator with sigma next to the target (no QZ confirmation needed: the spurious eigenvalues of
// the infinite Jordan blocks are ~1e7 away).
std::complex<double> nearest_eigenvalue(const Pencil& P, std::complex<double> target) {
  const std::complex<double> sigma = target + 1e-9 * (1.0 + std::abs(target));
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(P.A - sigma * P.B);
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> ces(lu.solve(P.B), false);
  if (ces.info() != Eigen::Success)
    throw std::runtime_error("light layer: complex Schur iteration did not converge");
  Eigen::Index i = 0;
  ces.eigenvalues().cwiseAbs().maxCoeff(&i);
  return sigma + 1.0 / ces.eigenvalues()(i);
}
}  // namespace

std::vector<std::complex<double>> light_layer_spectrum(const LinearBaseState& stress_free,
                                                       const LightLayerScaled& l, double k_hat,
                                                       int N, int M) {
  const LinearBaseState g = with_overburden(stress_free, l);
  const Pencil P = assemble_light_layer_pencil(g, l, k_hat, ChebyshevGrid(N), ChebyshevGrid(M));
  // The realified QZ of this larger pencil does not always converge (Eigen's RealQZ gave up for
  // the solver's fluid at N = M = 32): confirm with a second shift instead.
  const std::complex<double> shift = spectrum_shift(g, k_hat);
  return finite_eigenvalues_two_shifts(P, shift, shift + std::complex<double>(0.21, 0.37 * k_hat));
}

std::complex<double> nearest_light_layer_eigenvalue(const LinearBaseState& stress_free,
                                                    const LightLayerScaled& l, double k_hat, int N,
                                                    int M, std::complex<double> target) {
  return nearest_eigenvalue(assemble_light_layer_pencil(with_overburden(stress_free, l), l, k_hat,
                                                        ChebyshevGrid(N), ChebyshevGrid(M)),
                            target);
}

std::complex<double> continue_from_stress_free(const LinearBaseState& stress_free,
                                               const LightLayerScaled& l, double k_hat, int N,
                                               int M, std::complex<double> lambda_free,
                                               double step) {
  if (!(step > 1.0)) throw std::invalid_argument("light layer: continuation step must be > 1");
  const ChebyshevGrid grains(N), fluid(M);
  std::complex<double> lambda = lambda_free;
  for (double t = 1e-8;; t = std::min(1.0, t * step)) {
    const LightLayerScaled lt = l.scaled_by(t);
    lambda = nearest_eigenvalue(
        assemble_light_layer_pencil(with_overburden(stress_free, lt), lt, k_hat, grains, fluid),
        lambda);
    if (t == 1.0) return lambda;
  }
}

}  // namespace granbench::linear2d

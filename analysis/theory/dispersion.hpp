// Exact temporal dispersion relation of the depth-averaged mu(I) equations (Barker & Gray 2017,
// §7), generalised with a momentum shape factor chi (momentum flux chi h u^2 in (7.4); chi = 1 is
// the paper's model, chi = 5/4 the Bagnold profile's; docs/design.md §10).
//
// Linearising (7.3)-(7.4) about (h0, u_bar_0) in the scales of (7.13) gives (7.7) and
//   F^2 (du/dt + (2chi-1) du/dx + (chi-1) dh/dx) + dh/dx = Gamma (3/2 h - u) + F^2/R d2u/dx2,
// which reduces to (7.8) for chi = 1. With perturbations ~ exp(i k x + lambda t):
//
//   F^2 lambda^2 + (2 i chi F^2 k + Gamma + F^2 k^2/R) lambda
//        + (1 - chi F^2) k^2 + i (5/2) Gamma k + i F^2 k^3/R = 0,
//
// which for chi = 1 is (7.11) multiplied by i F^2/R. The growth rate is Re(lambda) and the
// phase speed -Im(lambda)/k; the unstable root is the one with the larger real part (docs/design.md
// §5). Long waves grow when F^2 (25/4 - 4 chi) > 1, i.e. F > 2/sqrt(25 - 16 chi) (= 2/3 for chi =
// 1).
#pragma once

#include <complex>
#include <optional>

#include "common/steady_state.hpp"

namespace granbench {

struct DispersionParams {
  double F = 0.0;      // Froude number (7.1)
  double R = 0.0;      // (7.6)
  double Gamma = 0.0;  // (7.9a)
  double chi = 1.0;    // momentum shape factor

  static DispersionParams from(const SteadyState& s, double chi = 1.0);
};

struct DispersionRoots {
  std::complex<double> unstable;  // larger real part
  std::complex<double> other;
};

// Both roots lambda_hat for the non-dimensional wavenumber k_hat.
DispersionRoots dispersion_roots(const DispersionParams& p, double k_hat);
// The characteristic polynomial, for checking roots: residual of the quadratic above.
std::complex<double> dispersion_polynomial(const DispersionParams& p, double k_hat,
                                           std::complex<double> lambda_hat);
// The paper's printed form (7.11) (chi = 1 only), for cross-checking.
std::complex<double> paper_polynomial_7_11(const DispersionParams& p, double k_hat,
                                           std::complex<double> lambda_hat);

// Long-wave critical Froude number for shape factor chi: 2/sqrt(25 - 16 chi).
double critical_froude(double chi);
// Temporal cutoff: the k_hat > 0 where Re(lambda_hat) of the unstable root crosses zero; empty
// when the flow is stable to long waves (F below critical).
std::optional<double> cutoff_k_hat(const DispersionParams& p);
// Closed form for chi = 1: k_c^2 = R Gamma (3F - 2)/(2 F^2).
double cutoff_k_hat_closed_form_chi1(const DispersionParams& p);
// Closed form for any chi, derived in dispersion.cpp: with v = chi + sqrt(chi^2 F^2 + 1 - chi
// F^2)/F the neutral wave speed (in units of u0), k_c^2 = R Gamma (5/2 - v) / (F^2 (v - 1)).
double cutoff_k_hat_closed_form(const DispersionParams& p);

// One mode in dimensional units (7.13): k_hat = 2 pi h0/Lx, lambda = lambda_hat u0/h0.
struct DispersionMode {
  double Lx = 0.0;
  double k_hat = 0.0;
  std::complex<double> lambda_hat;
  double growth_rate = 0.0;  // Re(lambda) [1/s]
  double phase_speed = 0.0;  // -Im(lambda)/k [m/s]
};
DispersionMode dispersion_mode(const SteadyState& s, double chi, double Lx);
double Lx_from_k_hat(const SteadyState& s, double k_hat);

}  // namespace granbench

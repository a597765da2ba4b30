// Finite eigenvalues and eigenvectors of the complex pencil A v = lambda B v of the 2D linear
// stability problem (analysis/linear2d/operator.hpp).
//
// B is singular: the incompressibility, constitutive and boundary rows carry no lambda, so most
// of the 4N + 5 eigenvalues of the pencil are infinite (only N are finite, as for the
// Orr-Sommerfeld problem). Eigen 3.4 has a generalised solver only for real pencils, so we use
// shift-and-invert: with a shift sigma that is not an eigenvalue,
//
//   M = (A - sigma B)^{-1} B,     M v = theta v,     lambda = sigma + 1/theta,
//
// and the infinite eigenvalues become theta = 0. M is complex and square, so Eigen's
// ComplexEigenSolver (complex Schur) applies. theta below a relative round-off floor (infinite
// eigenvalues, including the sqrt(eps)-perturbed ones of their Jordan blocks) and |lambda| above
// a cap are dropped. This costs about a third of a real QZ on the realified pencil of twice the
// size and returns each eigenvalue once (the realified pencil mixes in the complex conjugates).
// Eigenvectors are computed only for the modes asked for, by inverse iteration on A - lambda B,
// and each carries its relative residual.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "analysis/linear2d/operator.hpp"

namespace granbench::linear2d {

struct SpectrumOptions {
  double max_modulus = 1e8;       // |lambda| above this is treated as infinite
  double theta_floor = 1e-11;     // |theta| below this times max |theta| is an infinite eigenvalue
  double match_tolerance = 1e-6;  // relative agreement required between the two views
  double residual_tolerance = 1e-10;  // inverse-iteration residual that accepts a lone candidate
};

// Finite eigenvalues, sorted by decreasing real part. `shift` must not be an eigenvalue.
std::vector<std::complex<double>> finite_eigenvalues(const Pencil& P, std::complex<double> shift,
                                                     const SpectrumOptions& opt = {});

// The same without QZ: an eigenvalue is kept when shift-and-invert finds it at both shifts (the
// spurious values of the perturbed Jordan blocks move with the shift, finite eigenvalues do not).
// For pencils whose realified QZ does not converge (the light layer,
// analysis/linear2d/light_layer.hpp, whose pencil is larger and has more infinite eigenvalues).
std::vector<std::complex<double>> finite_eigenvalues_two_shifts(const Pencil& P,
                                                                std::complex<double> shift1,
                                                                std::complex<double> shift2,
                                                                const SpectrumOptions& opt = {});

// The finite eigenvalue nearest `target`, for callers that follow one mode (the continuation of
// the surface mode, the seed). Shift-and-invert alone gives the candidate; it is accepted when its
// inverse-iteration residual is at round-off. The spurious values of the perturbed Jordan blocks
// lie far from the shift with residuals of order 1 (0.36 for the §7 pencils against 1e-15 for
// finite modes), so a candidate that fails falls back to the nearest of finite_eigenvalues. This
// skips the realified QZ, which costs about twice the complex Schur, and returns the same value.
std::complex<double> nearest_finite_eigenvalue(const Pencil& P, std::complex<double> shift,
                                               std::complex<double> target,
                                               const SpectrumOptions& opt = {});

// The same eigenvalue by inverse iteration with the fixed shift `target`, for a caller whose target
// is close to it (the continuation of a branch): the dominant eigenvalue of (A - target B)^{-1} B
// is the finite one nearest target, reached at the rate |lambda_1 - target| / |lambda_2 -
// target| per iteration (8-30 iterations along the surface mode's path, about a tenth of a complex
// Schur's cost). Agrees with nearest_finite_eigenvalue to about 1e-12 relative; when it has not
// converged after `max_iterations` it returns nearest_finite_eigenvalue's value instead.
std::complex<double> nearest_eigenvalue_by_inverse_iteration(const Pencil& P,
                                                             std::complex<double> shift,
                                                             std::complex<double> target,
                                                             int max_iterations = 300,
                                                             const SpectrumOptions& opt = {});

struct Eigenpair {
  std::complex<double> lambda;  // scaled: growth = Re, phase speed = -Im/k_hat
  Eigen::VectorXcd v;           // eigenvector, |v| = 1
  double residual = 0.0;        // |A v - lambda B v| / (|A| + |lambda| |B|)
};

// Eigenvector of the finite eigenvalue `lambda` by inverse iteration.
Eigenpair eigenpair(const Pencil& P, std::complex<double> lambda);

}  // namespace granbench::linear2d

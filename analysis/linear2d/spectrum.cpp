// Shift-and-invert spectrum of the collocation pencil and inverse-iteration eigenvectors; the
// method is explained in analysis/linear2d/spectrum.hpp.
#include "analysis/linear2d/spectrum.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace granbench::linear2d {

namespace {

Eigen::MatrixXd realify(const Eigen::MatrixXcd& M) {
  const Eigen::Index n = M.rows();
  Eigen::MatrixXd R(2 * n, 2 * n);
  R << M.real(), -M.imag(), M.imag(), M.real();
  return R;
}

// Finite eigenvalues of the realified pencil: those of (A, B) and their conjugates, with the
// infinite ones removed by QZ itself (beta = 0 to round-off).
std::vector<std::complex<double>> realified_qz_eigenvalues(const Pencil& P, double cap) {
  const double eps = std::numeric_limits<double>::epsilon();
  Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> qz(realify(P.A), realify(P.B), false);
  if (qz.info() != Eigen::Success)
    throw std::runtime_error("linear stability: QZ iteration did not converge");
  std::vector<std::complex<double>> out;
  for (Eigen::Index i = 0; i < qz.alphas().size(); ++i) {
    const std::complex<double> alpha = qz.alphas()(i);
    const double beta = qz.betas()(i);
    if (std::abs(beta) <= 64.0 * eps * std::abs(alpha)) continue;
    const std::complex<double> lambda = alpha / beta;
    if (std::abs(lambda) < cap) out.push_back(lambda);
  }
  return out;
}

// Shift-and-invert eigenvalues: each eigenvalue of (A, B) once, plus spurious large ones from
// the perturbed Jordan blocks of the infinite eigenvalue.
std::vector<std::complex<double>> shift_invert_eigenvalues(const Pencil& P,
                                                           std::complex<double> shift,
                                                           const SpectrumOptions& opt) {
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(P.A - shift * P.B);
  const Eigen::MatrixXcd M = lu.solve(P.B);
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> ces(M, false);
  if (ces.info() != Eigen::Success)
    throw std::runtime_error("linear stability: complex Schur iteration did not converge");
  const Eigen::VectorXcd& theta = ces.eigenvalues();
  const double theta_max = theta.cwiseAbs().maxCoeff();
  std::vector<std::complex<double>> out;
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    if (!(std::abs(theta(i)) > opt.theta_floor * theta_max)) continue;  // lambda = infinity
    const std::complex<double> lambda = shift + 1.0 / theta(i);
    if (std::abs(lambda) < opt.max_modulus) out.push_back(lambda);
  }
  return out;
}

}  // namespace

std::vector<std::complex<double>> finite_eigenvalues(const Pencil& P, std::complex<double> shift,
                                                     const SpectrumOptions& opt) {
  const auto qz = realified_qz_eigenvalues(P, opt.max_modulus);
  std::vector<std::complex<double>> out;
  for (const auto& lambda : shift_invert_eigenvalues(P, shift, opt)) {
    const bool confirmed = std::any_of(qz.begin(), qz.end(), [&](const auto& mu) {
      return std::abs(mu - lambda) <= opt.match_tolerance * std::max(1.0, std::abs(lambda));
    });
    if (confirmed) out.push_back(lambda);
  }
  std::sort(out.begin(), out.end(), [](auto a, auto b) { return a.real() > b.real(); });
  return out;
}

std::vector<std::complex<double>> finite_eigenvalues_two_shifts(const Pencil& P,
                                                                std::complex<double> shift1,
                                                                std::complex<double> shift2,
                                                                const SpectrumOptions& opt) {
  const auto second = shift_invert_eigenvalues(P, shift2, opt);
  std::vector<std::complex<double>> out;
  for (const auto& lambda : shift_invert_eigenvalues(P, shift1, opt)) {
    const bool confirmed = std::any_of(second.begin(), second.end(), [&](const auto& mu) {
      return std::abs(mu - lambda) <= opt.match_tolerance * std::max(1.0, std::abs(lambda));
    });
    if (confirmed) out.push_back(lambda);
  }
  std::sort(out.begin(), out.end(), [](auto a, auto b) { return a.real() > b.real(); });
  return out;
}

std::complex<double> nearest_finite_eigenvalue(const Pencil& P, std::complex<double> shift,
                                               std::complex<double> target,
                                               const SpectrumOptions& opt) {
  const auto distance = [target](auto a, auto b) {
    return std::abs(a - target) < std::abs(b - target);
  };
  const auto candidates = shift_invert_eigenvalues(P, shift, opt);
  if (!candidates.empty()) {
    const auto best = *std::min_element(candidates.begin(), candidates.end(), distance);
    if (eigenpair(P, best).residual <= opt.residual_tolerance) return best;
  }
  const auto confirmed = finite_eigenvalues(P, shift, opt);
  if (confirmed.empty()) throw std::runtime_error("linear stability: no finite eigenvalue found");
  return *std::min_element(confirmed.begin(), confirmed.end(), distance);
}

std::complex<double> nearest_eigenvalue_by_inverse_iteration(const Pencil& P,
                                                             std::complex<double> shift,
                                                             std::complex<double> target,
                                                             int max_iterations,
                                                             const SpectrumOptions& opt) {
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(P.A - target * P.B);
  const Eigen::Index n = P.A.rows();
  Eigen::VectorXcd x = Eigen::VectorXcd::Ones(n) / std::sqrt(double(n));
  std::complex<double> lambda = target;
  for (int it = 0; it < max_iterations; ++it) {
    const Eigen::VectorXcd y = lu.solve(P.B * x);
    const double norm = y.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) break;  // target on an eigenvalue, or no mode
    const std::complex<double> next = target + 1.0 / x.dot(y);  // Rayleigh quotient, |x| = 1
    x = y / norm;
    if (std::abs(next - lambda) <= 1e-13 * std::abs(next)) return next;
    lambda = next;
  }
  return nearest_finite_eigenvalue(P, shift, target, opt);
}

Eigenpair eigenpair(const Pencil& P, std::complex<double> lambda) {
  // Inverse iteration: (A - lambda B) x_{j+1} = B x_j. With lambda accurate to round-off the
  // matrix is numerically singular and one or two steps give the eigenvector.
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(P.A - lambda * P.B);
  const Eigen::Index n = P.A.rows();
  Eigen::VectorXcd x = Eigen::VectorXcd::Ones(n) / std::sqrt(double(n));
  for (int it = 0; it < 3; ++it) {
    Eigen::VectorXcd y = lu.solve(P.B * x);
    const double norm = y.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) break;
    x = y / norm;
  }
  const double normA = P.A.cwiseAbs().rowwise().sum().maxCoeff();
  const double normB = P.B.cwiseAbs().rowwise().sum().maxCoeff();
  Eigenpair e;
  e.lambda = lambda;
  e.v = x;
  e.residual = (P.A * x - lambda * (P.B * x)).norm() / (normA + std::abs(lambda) * normB);
  return e;
}

}  // namespace granbench::linear2d

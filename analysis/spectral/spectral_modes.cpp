// Matrix pencil fit of damped complex exponentials; see spectral_modes.hpp.
#include "analysis/spectral/spectral_modes.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace granbench {

namespace {

using Matrix = Eigen::MatrixXcd;
using Vector = Eigen::VectorXcd;

// Pencil parameter: N/3, at least M, at most max_pencil, and small enough that the Hankel matrix
// has more rows than columns.
std::size_t pencil_parameter(std::size_t N, int M, std::size_t max_pencil) {
  const auto m = static_cast<std::size_t>(M);
  return std::max(m, std::min(N / 3, std::max(max_pencil, m)));
}

// Right singular vectors and singular values of the Hankel matrix of y (step 1-2).
struct HankelSvd {
  Matrix V;  // (L+1) x (L+1)
  Eigen::VectorXd sigma;
};

HankelSvd hankel_svd(std::span<const std::complex<double>> y, std::size_t L) {
  const std::size_t N = y.size();
  const auto rows = static_cast<Eigen::Index>(N - L), cols = static_cast<Eigen::Index>(L + 1);
  Matrix Y(rows, cols);
  for (Eigen::Index p = 0; p < rows; ++p)
    for (Eigen::Index q = 0; q < cols; ++q) Y(p, q) = y[static_cast<std::size_t>(p + q)];
  Eigen::BDCSVD<Matrix> svd(Y, Eigen::ComputeThinV);
  return {svd.matrixV(), svd.singularValues()};
}

// Steps 2-5 for M components from the Hankel SVD.
PencilFit fit_from_svd(std::span<const std::complex<double>> y, double dt, int M,
                       const HankelSvd& h) {
  const Eigen::Index L = h.V.rows() - 1;
  const Matrix VM = h.V.leftCols(M);
  const Matrix V1 = VM.topRows(L), V2 = VM.bottomRows(L);
  const Matrix X = V1.colPivHouseholderQr().solve(V2);  // (2)
  const Eigen::ComplexEigenSolver<Matrix> eig(X, false);
  const std::size_t N = y.size();
  std::vector<std::complex<double>> z(static_cast<std::size_t>(M));
  for (int j = 0; j < M; ++j) z[static_cast<std::size_t>(j)] = std::conj(eig.eigenvalues()(j));

  // Amplitudes: least squares of (1), Vandermonde P_nj = z_j^n.
  Matrix P(static_cast<Eigen::Index>(N), M);
  Vector b(static_cast<Eigen::Index>(N));
  for (int j = 0; j < M; ++j) {
    std::complex<double> zn = 1.0;
    for (std::size_t n = 0; n < N; ++n) {
      P(static_cast<Eigen::Index>(n), j) = zn;
      zn *= z[static_cast<std::size_t>(j)];
    }
  }
  for (std::size_t n = 0; n < N; ++n) b(static_cast<Eigen::Index>(n)) = y[n];
  const Vector a = P.colPivHouseholderQr().solve(b);

  PencilFit f;
  const double norm = b.norm();
  f.relative_residual = norm > 0.0 ? (P * a - b).norm() / norm : NAN;
  for (int j = 0; j < M; ++j)
    f.components.push_back({std::log(z[static_cast<std::size_t>(j)]) / dt, a(j)});  // step 3
  std::sort(f.components.begin(), f.components.end(), [](const auto& p, const auto& q) {
    return std::abs(p.amplitude) > std::abs(q.amplitude);
  });
  const Eigen::Index shown = std::min<Eigen::Index>(h.sigma.size(), 4);
  for (Eigen::Index i = 0; i < shown; ++i)
    f.singular_values.push_back(h.sigma(0) > 0.0 ? h.sigma(i) / h.sigma(0) : 0.0);
  return f;
}

bool finite(const PencilFit& f) {
  if (!std::isfinite(f.relative_residual)) return false;
  return std::all_of(f.components.begin(), f.components.end(), [](const auto& c) {
    return std::isfinite(c.lambda.real()) && std::isfinite(c.lambda.imag()) &&
           std::isfinite(c.amplitude.real()) && std::isfinite(c.amplitude.imag());
  });
}

// Every two components beat at least min_beats times over the window T.
bool resolved(const PencilFit& f, double T, double min_beats) {
  const double d_omega = 2.0 * std::numbers::pi * min_beats / T;
  for (std::size_t i = 0; i < f.components.size(); ++i)
    for (std::size_t j = i + 1; j < f.components.size(); ++j)
      if (std::fabs(f.components[i].lambda.imag() - f.components[j].lambda.imag()) < d_omega)
        return false;
  return true;
}

void check(std::span<const std::complex<double>> y, double dt, int M) {
  if (M < 1) throw std::invalid_argument("fit_exponentials: need at least one component");
  if (!(dt > 0.0))
    throw std::invalid_argument("fit_exponentials: the sample spacing must be positive");
  if (y.size() < pencil_min_samples(M))
    throw std::invalid_argument("fit_exponentials: too few samples for the number of components");
}

}  // namespace

std::size_t pencil_min_samples(int M) {
  return 3 * static_cast<std::size_t>(std::max(M, 1)) + 1;
}

PencilFit fit_exponentials(std::span<const std::complex<double>> y, double dt, int M,
                           std::size_t max_pencil) {
  check(y, dt, M);
  return fit_from_svd(y, dt, M, hankel_svd(y, pencil_parameter(y.size(), M, max_pencil)));
}

PencilFit fit_exponentials(std::span<const std::complex<double>> y, double dt,
                           const PencilOptions& opt) {
  check(y, dt, 1);
  // As many components as the samples allow, up to the maximum; one SVD serves every M.
  int M_max = std::max(1, opt.max_components);
  while (M_max > 1 && y.size() < pencil_min_samples(M_max)) --M_max;
  const HankelSvd h = hankel_svd(y, pencil_parameter(y.size(), M_max, opt.max_pencil));
  const double T = dt * static_cast<double>(y.size() - 1);
  PencilFit best;
  double best_score = INFINITY;
  bool best_meets = false;  // the kept fit meets target_residual
  for (int M = 1; M <= M_max; ++M) {
    PencilFit f = fit_from_svd(y, dt, M, h);
    if (!finite(f) || (M > 1 && !resolved(f, T, opt.min_beats))) continue;
    const bool meets = f.relative_residual <= opt.target_residual;
    const double score =
        std::max(f.relative_residual, opt.residual_floor) * std::pow(opt.improvement, M - 1);
    if ((meets && !best_meets) || (meets == best_meets && score < best_score)) {
      best_score = score;
      best_meets = meets;
      best = std::move(f);
    }
  }
  if (best.components.empty()) {  // one component is always admissible unless non-finite
    best = fit_from_svd(y, dt, 1, h);
  }
  return best;
}

}  // namespace granbench

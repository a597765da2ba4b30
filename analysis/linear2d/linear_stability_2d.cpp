// The 2D linear stability driver: spectrum at one wavenumber, the surface mode by continuation
// from the long-wave kinematic wave, the other unstable branches, and the convergence check.
#include "analysis/linear2d/linear_stability_2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "common/root_finding.hpp"

namespace granbench {
namespace linear2d {

double kinematic_speed(const LinearBaseState& b) {
  return b.profile == BaseProfile::Nusselt ? 3.0 : 2.5;  // d(h^{5/2})/dh, d(h^3)/dh at h = 1
}

double long_wave_growth_coefficient(const LinearBaseState& b) {
  if (b.profile != BaseProfile::Bagnold)
    throw std::invalid_argument("long-wave coefficient derived for the Bagnold state only");
  return 2.5 / b.Gamma * (0.625 * b.F * b.F - 0.4 + 0.6 * b.mu * b.q);
}

double critical_froude_2d(double mu, double Gamma) {
  const double q = mu - 0.5 * Gamma;  // (3.3b)
  return std::sqrt(std::max(0.0, 0.32 * (2.0 - 3.0 * mu * q)));
}

namespace {
// A shift for shift-and-invert that sits between the surface velocity and the kinematic speed
// and slightly to the unstable side: near the surface mode, and not on the line -i k U0(z)
// where critical-layer modes accumulate.
std::complex<double> default_shift(const LinearBaseState& b, double k_hat) {
  return {0.05, -0.5 * (kinematic_speed(b) + b.U_surface()) * k_hat - 0.0137};
}

std::complex<double> nearest(const std::vector<std::complex<double>>& set,
                             std::complex<double> target) {
  if (set.empty()) throw std::runtime_error("linear stability: no finite eigenvalue found");
  return *std::min_element(set.begin(), set.end(), [&](auto a, auto b) {
    return std::abs(a - target) < std::abs(b - target);
  });
}

// The mode at k_hat nearest `target` (spectrum's pencil and shift, without the full spectrum).
std::complex<double> nearest_mode(const LinearBaseState& b, double k_hat, int N, VerticalMap map,
                                  std::complex<double> target) {
  if (!(k_hat > 0.0)) throw std::invalid_argument("linear stability needs k_hat > 0");
  return nearest_finite_eigenvalue(assemble_pencil(b, k_hat, ChebyshevGrid(N), map),
                                   default_shift(b, k_hat), target);
}

// The same along a path, where the target is close: by inverse iteration.
std::complex<double> followed_mode(const LinearBaseState& b, double k_hat, int N, VerticalMap map,
                                   std::complex<double> target) {
  if (!(k_hat > 0.0)) throw std::invalid_argument("linear stability needs k_hat > 0");
  return nearest_eigenvalue_by_inverse_iteration(assemble_pencil(b, k_hat, ChebyshevGrid(N), map),
                                                 default_shift(b, k_hat), target);
}
}  // namespace

std::vector<std::complex<double>> spectrum(const LinearBaseState& b, double k_hat, int N,
                                           VerticalMap map) {
  if (!(k_hat > 0.0)) throw std::invalid_argument("linear stability needs k_hat > 0");
  const ChebyshevGrid grid(N);
  return finite_eigenvalues(assemble_pencil(b, k_hat, grid, map), default_shift(b, k_hat));
}

namespace {
// The surface mode at k_hat traced from the kinematic wave along path (at path.N, in the map
// that suits the viscosity profile): a guess that steers the choice among the spectrum's modes.
std::complex<double> traced_surface_mode(const LinearBaseState& b, double k_hat,
                                         const ContinuationOptions& path) {
  // Long-wave limit: lambda = -i c k (kinematic wave) + O(k^2). The expansion holds only for
  // k_hat well below Gamma/F^2 (~1e-3 for the §7 case), so the start of the path is lowered
  // until an eigenvalue sits within 5% of the kinematic wave.
  // The path always uses the map that suits the viscosity profile; the callers apply theirs.
  const VerticalMap path_map = b.beta > 0.0 ? VerticalMap::SquareRoot : VerticalMap::Linear;
  const double c = kinematic_speed(b);
  double k = std::min(k_hat, path.k_start);
  std::complex<double> guess(0.0, -c * k);
  std::complex<double> lambda = followed_mode(b, k, path.N, path_map, guess);
  while (std::abs(lambda - guess) > 0.05 * c * k && k > 1e-8) {
    k *= 0.1;
    guess = {0.0, -c * k};
    lambda = followed_mode(b, k, path.N, path_map, guess);
  }
  if (std::abs(lambda - guess) > 0.05 * c * k)
    throw std::runtime_error("linear stability: no kinematic wave found in the long-wave limit");
  while (k < k_hat) {
    const double k_next = std::min(k_hat, k * path.step_ratio);
    guess = lambda * (k_next / k);  // phase speed and growth/k vary slowly along the branch
    lambda = followed_mode(b, k_next, path.N, path_map, guess);
    k = k_next;
  }
  return lambda;
}
}  // namespace

std::complex<double> surface_mode_eigenvalue(const LinearBaseState& b, double k_hat, int N,
                                             VerticalMap map, const ContinuationOptions& path) {
  // The path only steers: the eigenvalue returned is always the spectrum's at (N, map).
  return nearest_mode(b, k_hat, N, map, traced_surface_mode(b, k_hat, path));
}

std::optional<double> surface_mode_cutoff_k_hat(const LinearBaseState& b, int N, VerticalMap map,
                                                const ContinuationOptions& path, double k_max) {
  double k = path.k_start;
  std::complex<double> lambda = followed_mode(b, k, N, map, traced_surface_mode(b, k, path));
  if (!(lambda.real() > 0.0)) return std::nullopt;
  // Steps of 20 % (the path's are 30 %) keep each guess, the last eigenvalue scaled with k, close
  // enough to the surface mode that inverse iteration stays on its branch.
  for (;;) {
    const double k_next = k * 1.2;
    if (k_next > k_max) return std::nullopt;
    const auto next = followed_mode(b, k_next, N, map, lambda * (k_next / k));
    if (!(next.real() > 0.0)) break;
    k = k_next;
    lambda = next;
  }
  // Every evaluation inside the bracket [k, 1.2 k] starts from its lower end's eigenvalue.
  const auto growth = [&, k_low = k, lambda_low = lambda](double kk) {
    return followed_mode(b, kk, N, map, lambda_low * (kk / k_low)).real();
  };
  return brent_root(growth, k, 1.2 * k, 1e-10);
}

double scaled_wavenumber(const SteadyState& s, double Lx) {
  if (!(Lx > 0.0)) throw std::invalid_argument("linear stability needs Lx > 0");
  return 2.0 * std::numbers::pi * s.h0 / Lx;  // (7.13b)
}

Eigenpair surface_mode(const LinearBaseState& b, double k_hat, int N, VerticalMap map,
                       const ContinuationOptions& path) {
  if (N < 4) throw std::invalid_argument("linear stability needs N >= 4");
  // As linear_stability_2d picks it: continued at path.N, the nearest mode at path.N in `map`,
  // then the nearest at N. Here each nearest mode comes from inverse iteration, which reaches the
  // eigenvalue nearest its target without the full spectrum's Schur decompositions (they were
  // 13 ms of the 45 ms that a 2D run spent before its first step; docs/performance.md); it
  // agrees with the spectrum's to about 1e-12 and falls back to it when it does not converge.
  const std::complex<double> continued =
      followed_mode(b, k_hat, path.N, map, traced_surface_mode(b, k_hat, path));
  const Pencil P = assemble_pencil(b, k_hat, ChebyshevGrid(N), map);
  return eigenpair(P,
                   nearest_eigenvalue_by_inverse_iteration(P, default_shift(b, k_hat), continued));
}

std::vector<BranchPoint> surface_branch(const LinearBaseState& b, const std::vector<double>& k_hat,
                                        int N, const ContinuationOptions& path) {
  if (!std::is_sorted(k_hat.begin(), k_hat.end()))
    throw std::invalid_argument("surface_branch needs increasing k_hat");
  std::vector<BranchPoint> out;
  std::complex<double> lambda;
  double k_prev = 0.0;
  for (double k : k_hat) {
    const auto eig = spectrum(b, k, N);
    // First point by continuation from the long-wave limit; then from the previous point.
    lambda = out.empty()
                 ? nearest(eig, surface_mode_eigenvalue(b, k, N, VerticalMap::SquareRoot, path))
                 : nearest(eig, lambda * (k / k_prev));
    BranchPoint p;
    p.k_hat = k;
    p.surface = lambda;
    p.other_max_growth = std::numeric_limits<double>::quiet_NaN();
    for (const auto& l : eig) {  // sorted by decreasing real part
      if (l == lambda) continue;
      p.other_max_growth = l.real();
      p.other_phase_speed = -l.imag() / k;
      break;
    }
    out.push_back(p);
    k_prev = k;
  }
  return out;
}

}  // namespace linear2d

namespace {

Linear2DMode make_mode(std::complex<double> lambda_hat, double k_hat, const SteadyState& s) {
  Linear2DMode m;
  m.lambda_hat = lambda_hat;
  m.growth_rate = lambda_hat.real() * s.u_mean / s.h0;    // (7.13a)
  m.phase_speed = -lambda_hat.imag() / k_hat * s.u_mean;  // -Im(lambda)/k, k = k_hat/h0
  return m;
}

void attach_check(Linear2DMode& m, const std::vector<std::complex<double>>& finer) {
  if (finer.empty()) return;
  m.lambda_hat_check = linear2d::nearest(finer, m.lambda_hat);
  m.relative_difference =
      std::abs(m.lambda_hat - m.lambda_hat_check) / std::abs(m.lambda_hat_check);
}

// The light-layer counterparts of the stress-free modes of r, and the layer's own unstable modes.
Linear2DLightLayerResult light_layer_modes(const SteadyState& s, const Linear2DResult& r,
                                           const linear2d::LightLayer& layer) {
  using namespace linear2d;
  Linear2DLightLayerResult out;
  out.layer = layer;
  out.scaled = scale(layer, s);
  const auto& l = out.scaled;
  auto mode = [&](std::complex<double> lambda_free, bool surface) {
    const auto lambda = continue_from_stress_free(r.base, l, r.k_hat, r.N, r.N, lambda_free);
    Linear2DMode m = make_mode(lambda, r.k_hat, s);
    m.surface = surface;
    if (r.N_check > 0) {
      m.lambda_hat_check =
          nearest_light_layer_eigenvalue(r.base, l, r.k_hat, r.N_check, r.N_check, lambda);
      m.relative_difference =
          std::abs(m.lambda_hat - m.lambda_hat_check) / std::abs(m.lambda_hat_check);
    }
    return m;
  };
  out.surface = mode(r.surface.lambda_hat, true);
  for (const auto& u : r.unstable)
    out.continued.push_back(u.surface ? out.surface : mode(u.lambda_hat, false));
  for (const auto& l_hat : light_layer_spectrum(r.base, l, r.k_hat, r.N, r.N)) {
    if (!(l_hat.real() > 0.0)) break;  // sorted by decreasing real part
    Linear2DMode m = make_mode(l_hat, r.k_hat, s);
    m.surface = std::abs(l_hat - out.surface.lambda_hat) <= 1e-8 * std::abs(l_hat);
    out.unstable.push_back(m);
  }
  return out;
}

}  // namespace

Linear2DResult linear_stability_2d(const SteadyState& s, const MuCurve& curve, double Lx,
                                   const Linear2DOptions& opt) {
  using namespace linear2d;
  if (opt.N < 4) throw std::invalid_argument("linear stability needs N >= 4");
  Linear2DResult r;
  r.Lx = Lx;
  r.k_hat = scaled_wavenumber(s, Lx);
  r.N = opt.N;
  r.N_check = opt.N_check > opt.N ? opt.N_check : 0;
  r.base = mu_i_base_state(s, curve);

  const ChebyshevGrid grid(opt.N);
  const Pencil P = assemble_pencil(r.base, r.k_hat, grid, opt.map);
  const auto eig = finite_eigenvalues(P, default_shift(r.base, r.k_hat));
  const auto surface_path = surface_mode_eigenvalue(r.base, r.k_hat, opt.path.N, opt.map, opt.path);
  const std::complex<double> surface_lambda = nearest(eig, surface_path);
  std::vector<std::complex<double>> finer;
  if (r.N_check > 0) finer = spectrum(r.base, r.k_hat, r.N_check, opt.map);

  r.surface = make_mode(surface_lambda, r.k_hat, s);
  r.surface.surface = true;
  attach_check(r.surface, finer);
  for (const auto& l : eig) {
    if (!(l.real() > 0.0)) break;  // sorted by decreasing real part
    Linear2DMode m = make_mode(l, r.k_hat, s);
    m.surface = (l == surface_lambda);
    attach_check(m, finer);
    r.unstable.push_back(m);
  }
  r.surface_pair = eigenpair(P, surface_lambda);
  if (opt.light_layer) r.light_layer = light_layer_modes(s, r, *opt.light_layer);
  return r;
}

}  // namespace granbench

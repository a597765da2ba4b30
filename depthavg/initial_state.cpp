// Initial states (7.2) and the normal mode (7.10) of (7.7)-(7.8); see initial_state.hpp.
#include "depthavg/initial_state.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace granbench::depthavg {

std::vector<double> initial_state(const Rhs& rhs, const InitialParams& init,
                                  std::complex<double> lambda_hat) {
  const SteadyState& base = rhs.base();
  const std::size_t nx = rhs.nx();
  if (init.mode < 1) throw std::invalid_argument("initial state: mode must be >= 1");
  const double k = 2.0 * std::numbers::pi * init.mode / rhs.space().Lx;  // [1/m]
  const double eps = init.a0 / base.h0;

  std::vector<double> h(nx), u(nx);
  if (init.kind == InitKind::Sine) {
    for (std::size_t j = 0; j < nx; ++j)
      h[j] = base.h0 + init.a0 * std::sin(k * rhs.x(j));  // (7.2)
  } else {
    const std::complex<double> I(0.0, 1.0);
    const double k_hat = k * base.h0;
    const std::complex<double> u_t = -(lambda_hat + I * k_hat) / (I * k_hat);  // (7.7)
    for (std::size_t j = 0; j < nx; ++j) {
      const std::complex<double> e = std::exp(I * (k * rhs.x(j)));  // (7.10)
      h[j] = base.h0 * (1.0 + eps * e.real());
      u[j] = base.u_mean * (1.0 + eps * (u_t * e).real());
    }
  }
  if (init.noise > 0.0) {
    std::mt19937_64 gen(init.seed);
    std::uniform_real_distribution<double> dist(-1.0, 1.0);
    std::vector<double> xi(nx);
    double mean = 0.0;
    for (double& v : xi) mean += (v = dist(gen)) / static_cast<double>(nx);
    for (std::size_t j = 0; j < nx; ++j) h[j] += init.noise * base.h0 * (xi[j] - mean);
  }
  std::vector<double> U(2 * nx);
  for (std::size_t j = 0; j < nx; ++j) {
    if (!(h[j] > 0.0))
      throw std::invalid_argument("initial state: a0/noise make the depth negative");
    // Sine: the steady Bagnold state at the local depth (§7); eigenmode: the mode's velocity
    // (noise leaves u unchanged).
    const double uj = init.kind == InitKind::Sine ? base.mean_velocity_at_depth(h[j]) : u[j];
    U[2 * j] = h[j];
    U[2 * j + 1] = h[j] * uj;
  }
  return U;
}

}  // namespace granbench::depthavg

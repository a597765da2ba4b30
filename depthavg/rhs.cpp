// The right-hand side of the depth-averaged mu(I) equations (7.3)-(7.4): reconstruction, the
// central-upwind flux, the viscous face flux and the friction source. See rhs.hpp for the scheme.
#include "rhs.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granbench::depthavg {

namespace {

double minmod(double a, double b) {
  if (a * b <= 0.0) return 0.0;
  return a > 0.0 ? std::min(a, b) : std::max(a, b);
}

// Physical flux and characteristic speeds of (h, q) with momentum flux chi q u + g' h^2/2.
// In a frame moving at speed c the fluxes gain -c U (see rhs.hpp).
struct FaceState {
  double h, u, q;
  double flux_h(double c) const { return q - c * h; }                       // (7.3)
  double flux_q(double chi, double g_cos, double c) const {
    return chi * q * u + 0.5 * g_cos * h * h - c * q;                       // (7.4)
  }
  double celerity(double chi, double g_cos) const {
    return std::sqrt(std::max(0.0, chi * (chi - 1.0) * u * u + g_cos * h));
  }
};

}  // namespace

Rhs::Rhs(const SteadyState& base, const MuCurve& curve, const SpaceParams& space)
    : base_(base), curve_(curve), space_(space) {
  if (space_.nx < 2 * stencil_radius + 1)
    throw std::invalid_argument("depthavg: nx must be at least 5");
  if (!(space_.Lx > 0.0)) throw std::invalid_argument("depthavg: Lx must be positive");
  if (!(space_.chi >= 1.0)) throw std::invalid_argument("depthavg: chi must be >= 1");
  dx_ = space_.Lx / static_cast<double>(space_.nx);
  g_cos_ = base_.material.g * std::cos(base_.zeta);
  tan_zeta_ = std::tan(base_.zeta);
  h_dry_ = space_.h_dry_fraction * base_.h0;
  // I = 5 d u / (2 h^{3/2} sqrt(phi g cos zeta)) is linear in u h^{-3/2}: keep its prefactor.
  inertial_scale_ = depth_averaged_inertial_number(base_.material, base_.zeta, 1.0, 1.0);
  slope_h_.resize(space_.nx);
  slope_q_.resize(space_.nx);
  face_flux_h_.resize(space_.nx);
  face_flux_q_.resize(space_.nx);
}

double Rhs::velocity(double h, double q) const {
  // u = q/h for h >= h_dry; smoothly to zero below (Kurganov & Petrova 2007).
  const double h4 = h * h * h * h;
  const double e4 = h_dry_ * h_dry_ * h_dry_ * h_dry_;
  return std::sqrt(2.0) * h * q / std::sqrt(h4 + std::max(h4, e4));
}

double Rhs::momentum_source(double h, double q) const {
  if (h <= 0.0) return 0.0;
  const double u = velocity(h, q);
  const double I = inertial_scale_ * std::fabs(u) / (h * std::sqrt(h));  // DESIGN.md §4, (7.1)
  double mu;
  if (u != 0.0 && I > 0.0) {
    mu = std::copysign(curve_.mu(I), u);
  } else {
    // At rest: static friction balances gravity up to the curve's value at I -> 0+.
    mu = std::min(tan_zeta_, curve_.mu(1e-300));
  }
  return g_cos_ * h * (tan_zeta_ - mu);  // (7.4): h g cos(zeta) (tan(zeta) - mu)
}

double Rhs::slope(double left, double centre, double right) const {
  const double dm = centre - left, dp = right - centre;
  switch (space_.reconstruction) {
    case Reconstruction::Central:
      return 0.5 * (dm + dp);
    case Reconstruction::Minmod:
      return minmod(dm, dp);
    case Reconstruction::MC:
      return minmod(minmod(2.0 * dm, 2.0 * dp), 0.5 * (dm + dp));
    case Reconstruction::VanAlbada:  // smooth: dm dp (dm + dp) / (dm^2 + dp^2)
      return dm * dp * (dm + dp) / (dm * dm + dp * dp + 1e-300);
  }
  return 0.0;
}

void Rhs::operator()(std::span<const double> U, std::span<double> dUdt) const {
  const std::size_t n = space_.nx;
  const double chi = space_.chi;
  const double cf = space_.frame_speed;
  auto H = [&](std::size_t j) { return U[2 * j]; };
  auto Q = [&](std::size_t j) { return U[2 * j + 1]; };

  // 1. Slopes (as differences across a cell), periodic; h kept non-negative at the faces.
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t jm = (j + n - 1) % n, jp = (j + 1) % n;
    double sh = slope(H(jm), H(j), H(jp));
    if (std::fabs(sh) > 2.0 * std::max(H(j), 0.0)) sh = std::copysign(2.0 * std::max(H(j), 0.0), sh);
    slope_h_[j] = sh;
    slope_q_[j] = slope(Q(jm), Q(j), Q(jp));
  }

  // 2. Central-upwind flux at face j+1/2 (between cells j and j+1), minus the viscous flux.
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t jp = (j + 1) % n;
    FaceState L, R;
    L.h = H(j) + 0.5 * slope_h_[j];
    R.h = H(jp) - 0.5 * slope_h_[jp];
    L.u = velocity(L.h, Q(j) + 0.5 * slope_q_[j]);
    R.u = velocity(R.h, Q(jp) - 0.5 * slope_q_[jp]);
    L.q = L.h * L.u;
    R.q = R.h * R.u;
    const double cL = L.celerity(chi, g_cos_), cR = R.celerity(chi, g_cos_);
    const double ap = std::max({chi * L.u + cL - cf, chi * R.u + cR - cf, 0.0});
    const double am = std::min({chi * L.u - cL - cf, chi * R.u - cR - cf, 0.0});
    double fh, fq;
    if (ap - am > 1e-300) {
      const double w = 1.0 / (ap - am);
      fh = w * (ap * L.flux_h(cf) - am * R.flux_h(cf) + ap * am * (R.h - L.h));
      fq = w * (ap * L.flux_q(chi, g_cos_, cf) - am * R.flux_q(chi, g_cos_, cf) +
                ap * am * (R.q - L.q));
    } else {
      fh = 0.5 * (L.flux_h(cf) + R.flux_h(cf));
      fq = 0.5 * (L.flux_q(chi, g_cos_, cf) + R.flux_q(chi, g_cos_, cf));
    }
    if (space_.viscous) {
      const double hf = 0.5 * (std::max(H(j), 0.0) + std::max(H(jp), 0.0));
      const double du = velocity(H(jp), Q(jp)) - velocity(H(j), Q(j));
      fq -= base_.nu * hf * std::sqrt(hf) * du / dx_;  // (7.4): nu h^{3/2} du/dx
    }
    face_flux_h_[j] = fh;
    face_flux_q_[j] = fq;
  }

  // 3. Flux differences and the friction/gravity source.
  const double inv_dx = 1.0 / dx_;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t jm = (j + n - 1) % n;
    dUdt[2 * j] = -(face_flux_h_[j] - face_flux_h_[jm]) * inv_dx;  // (7.3)
    dUdt[2 * j + 1] =
        -(face_flux_q_[j] - face_flux_q_[jm]) * inv_dx + momentum_source(H(j), Q(j));  // (7.4)
  }
}

}  // namespace granbench::depthavg

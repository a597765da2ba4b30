// The right-hand side of the depth-averaged mu(I) equations (7.3)-(7.4): reconstruction, the
// central-upwind flux, the viscous face flux and the friction source. See rhs.hpp for the scheme.
#include "depthavg/rhs.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granbench::depthavg {

namespace {

double minmod(double a, double b) {
  // 0 when a, b differ in sign, else the one nearer zero (branch-free, so the loop vectorises)
  const double m = std::fabs(a) < std::fabs(b) ? a : b;
  return a * b > 0.0 ? m : 0.0;
}

// Slope of the reconstruction (as a difference across the cell) from the left and right
// differences; R is fixed per call, so the loop holds no switch.
template <Reconstruction R>
double limited_slope(double dm, double dp) {
  if constexpr (R == Reconstruction::Central) return 0.5 * (dm + dp);
  if constexpr (R == Reconstruction::Minmod) return minmod(dm, dp);
  if constexpr (R == Reconstruction::MC) return minmod(minmod(2.0 * dm, 2.0 * dp), 0.5 * (dm + dp));
  if constexpr (R == Reconstruction::VanAlbada)  // smooth: dm dp (dm + dp) / (dm^2 + dp^2)
    return dm * dp * (dm + dp) / (dm * dm + dp * dp + 1e-300);
  return 0.0;
}

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
  mu_rest_ = std::min(tan_zeta_, curve_.mu(1e-300));
  const std::size_t n = space_.nx + 2 * ghost;
  for (auto* v : {&h_, &q_, &u_, &slope_h_, &slope_q_, &face_flux_h_, &face_flux_q_}) v->resize(n);
  inertial_.resize(space_.nx);
  mu_.resize(space_.nx);
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
  const double I = inertial_scale_ * std::fabs(u) / (h * std::sqrt(h));  // docs/design.md §4, (7.1)
  // At rest: static friction balances gravity up to the curve's value at I -> 0+.
  const double mu = (u != 0.0 && I > 0.0) ? std::copysign(curve_.mu(I), u) : mu_rest_;
  return g_cos_ * h * (tan_zeta_ - mu);  // (7.4): h g cos(zeta) (tan(zeta) - mu)
}

// Central-upwind flux minus the viscous flux at face f - 1/2 (between cells f-1 and f, array
// indices f-1+ghost and f+ghost), for f = 0 .. nx, stored at index f. Needs the slopes of cells
// -1 .. nx.
template <Reconstruction R>
void Rhs::face_fluxes() const {
  const std::size_t n = space_.nx, g = ghost;
  const double chi = space_.chi, cf = space_.frame_speed, g_cos = g_cos_;
  const double e4 = h_dry_ * h_dry_ * h_dry_ * h_dry_;
  const double nu_dx = space_.viscous ? base_.nu / dx_ : 0.0;
  const double* h = h_.data();
  const double* q = q_.data();
  const double* u = u_.data();
  double* sh = slope_h_.data();
  double* sq = slope_q_.data();
  double* fh_out = face_flux_h_.data();
  double* fq_out = face_flux_q_.data();

  // 1. Slopes of cells -1 .. nx; h kept non-negative at the faces.
  for (std::size_t i = g - 1; i <= n + g; ++i) {
    const double s = limited_slope<R>(h[i] - h[i - 1], h[i + 1] - h[i]);
    const double cap = 2.0 * std::max(h[i], 0.0);
    sh[i] = std::fabs(s) > cap ? std::copysign(cap, s) : s;
    sq[i] = limited_slope<R>(q[i] - q[i - 1], q[i + 1] - q[i]);
  }

  // 2. Face states, speeds a+- (characteristic speeds chi u +- c, shifted by -c_frame) and the
  //    central-upwind flux H of Kurganov, Noelle & Petrova (rhs.hpp).
  auto vel = [e4](double hh, double qq) {  // Rhs::velocity, inlined
    const double h4 = hh * hh * hh * hh;
    return std::sqrt(2.0) * hh * qq / std::sqrt(h4 + std::max(h4, e4));
  };
  const std::size_t faces = n + 1;
  for (std::size_t f = 0; f < faces; ++f) {
    const std::size_t l = f + (g - 1), r = f + g;
    const double hL = h[l] + 0.5 * sh[l], hR = h[r] - 0.5 * sh[r];
    const double uL = vel(hL, q[l] + 0.5 * sq[l]), uR = vel(hR, q[r] - 0.5 * sq[r]);
    const double qL = hL * uL, qR = hR * uR;
    const double cL = std::sqrt(std::max(0.0, chi * (chi - 1.0) * uL * uL + g_cos * hL));
    const double cR = std::sqrt(std::max(0.0, chi * (chi - 1.0) * uR * uR + g_cos * hR));
    const double ap = std::max(std::max(chi * uL + cL - cf, chi * uR + cR - cf), 0.0);
    const double am = std::min(std::min(chi * uL - cL - cf, chi * uR - cR - cf), 0.0);
    const double fhL = qL - cf * hL, fhR = qR - cf * hR;                 // (7.3)
    const double fqL = chi * qL * uL + 0.5 * g_cos * hL * hL - cf * qL;  // (7.4)
    const double fqR = chi * qR * uR + 0.5 * g_cos * hR * hR - cf * qR;
    // ap - am = 0 only where both faces are dry and still: the flux is then the plain average.
    const bool spread = ap - am > 1e-300;
    const double w = 1.0 / std::max(ap - am, 1e-300);
    const double fh = spread ? w * (ap * fhL - am * fhR + ap * am * (hR - hL)) : 0.5 * (fhL + fhR);
    double fq = spread ? w * (ap * fqL - am * fqR + ap * am * (qR - qL)) : 0.5 * (fqL + fqR);
    // viscous face flux nu h_f^{3/2} (u_r - u_l)/dx of (7.4)
    const double hf = 0.5 * (std::max(h[l], 0.0) + std::max(h[r], 0.0));
    fq -= nu_dx * hf * std::sqrt(hf) * (u[r] - u[l]);
    fh_out[f] = fh;
    fq_out[f] = fq;
  }
}

void Rhs::operator()(std::span<const double> U, std::span<double> dUdt) const {
  const std::size_t n = space_.nx, g = ghost;
  double* h = h_.data();
  double* q = q_.data();
  double* u = u_.data();

  // 0. (h, q) into contiguous arrays with periodic ghost cells; u once per cell.
  for (std::size_t j = 0; j < n; ++j) {
    h[j + g] = U[2 * j];
    q[j + g] = U[2 * j + 1];
  }
  for (std::size_t k = 0; k < g; ++k) {
    h[k] = h[n + k];
    q[k] = q[n + k];
    h[n + g + k] = h[g + k];
    q[n + g + k] = q[g + k];
  }
  const double e4 = h_dry_ * h_dry_ * h_dry_ * h_dry_;
  for (std::size_t i = 0; i < n + 2 * g; ++i) {
    const double h4 = h[i] * h[i] * h[i] * h[i];
    u[i] = std::sqrt(2.0) * h[i] * q[i] / std::sqrt(h4 + std::max(h4, e4));  // Rhs::velocity
  }

  // 1.-2. Fluxes at the faces -1/2 .. nx - 1/2.
  switch (space_.reconstruction) {
    case Reconstruction::Central:
      face_fluxes<Reconstruction::Central>();
      break;
    case Reconstruction::Minmod:
      face_fluxes<Reconstruction::Minmod>();
      break;
    case Reconstruction::MC:
      face_fluxes<Reconstruction::MC>();
      break;
    case Reconstruction::VanAlbada:
      face_fluxes<Reconstruction::VanAlbada>();
      break;
  }

  // 3. Friction mu(I) once per cell, at I = inertial_scale |u| / h^{3/2} (docs/design.md §4,
  // (7.1)).
  double* I = inertial_.data();
  for (std::size_t j = 0; j < n; ++j) {
    const double hj = std::max(h[j + g], 1e-100);
    I[j] = inertial_scale_ * std::fabs(u[j + g]) / (hj * std::sqrt(hj));
  }
  curve_.mu_many(inertial_, mu_);

  // 4. Flux differences and the friction/gravity source (momentum_source, cell by cell).
  const double inv_dx = 1.0 / dx_;
  const double* fh = face_flux_h_.data();
  const double* fq = face_flux_q_.data();
  const double* mu = mu_.data();
  for (std::size_t j = 0; j < n; ++j) {
    const double hj = h[j + g], uj = u[j + g];
    // at rest (u = 0, or I = 0) static friction balances gravity up to mu(0+)
    const double m = ((uj != 0.0) & (I[j] > 0.0)) ? std::copysign(mu[j], uj) : mu_rest_;
    const double source = hj > 0.0 ? g_cos_ * hj * (tan_zeta_ - m) : 0.0;  // (7.4)
    dUdt[2 * j] = -(fh[j + 1] - fh[j]) * inv_dx;                           // (7.3)
    dUdt[2 * j + 1] = -(fq[j + 1] - fq[j]) * inv_dx + source;              // (7.4)
  }
}

}  // namespace granbench::depthavg

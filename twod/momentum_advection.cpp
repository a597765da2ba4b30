// The advective acceleration (u . grad) u of (2.10), explicit in time.
//
// On each staggered control volume (around a u-face or a w-face) the flux form
//   (u . grad) q = div(u q) - q div(u)
// is evaluated with the advecting velocity averaged to the control-volume faces and the
// advected component q reconstructed upwind with a van Leer-limited slope (second order where
// smooth, no new extrema; stable for the Courant numbers < 1/2 the VOF already imposes). The
// - q div(u) term removes the discrete divergence of the averaged advecting field.
// Boundaries: no flux through the bed; at the top q is extended with zero gradient.
#include "twod/momentum_advection.hpp"

#include <algorithm>

namespace granbench::twod {

namespace {
double van_leer(double a, double b) {
  return a * b > 0.0 ? 2.0 * a * b / (a + b) : 0.0;
}

// Upwind-reconstructed face value between q1 (behind) and q2 (ahead) for velocity V, with q0
// before q1 and q3 after q2.
double upwind(double V, double q0, double q1, double q2, double q3) {
  if (V >= 0.0) return q1 + 0.5 * van_leer(q1 - q0, q2 - q1);
  return q2 - 0.5 * van_leer(q2 - q1, q3 - q2);
}
}  // namespace

void momentum_advection(const Grid& g, const Fields& s, std::vector<double>& adv_u,
                        std::vector<double>& adv_w) {
  const int nx = g.nx, nz = g.nz;
  const auto &u = s.u, &w = s.w;
  adv_u.assign(g.cells(), 0.0);
  adv_w.assign(g.w_faces(), 0.0);
  auto U = [&](int i, int k) { return u[g.at(i, std::clamp(k, 0, nz - 1))]; };
  auto W = [&](int i, int k) { return w[g.at(i, std::clamp(k, 0, nz))]; };

  // x-momentum on the control volume of u-face (i, k). (Rows in parallel: each entry is written
  // once; parallel.hpp.)
#pragma omp parallel for schedule(static)
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      // x-fluxes at cell centres i-1 (left) and i (right)
      const double Vl = 0.5 * (U(i - 1, k) + U(i, k)), Vr = 0.5 * (U(i, k) + U(i + 1, k));
      const double ql = upwind(Vl, U(i - 2, k), U(i - 1, k), U(i, k), U(i + 1, k));
      const double qr = upwind(Vr, U(i - 1, k), U(i, k), U(i + 1, k), U(i + 2, k));
      // z-fluxes at corners (i, k) (bottom) and (i, k+1) (top)
      const double Wb = k == 0 ? 0.0 : 0.5 * (W(i - 1, k) + W(i, k));
      const double Wt = 0.5 * (W(i - 1, k + 1) + W(i, k + 1));
      const double qb = k == 0 ? 0.0 : upwind(Wb, U(i, k - 2), U(i, k - 1), U(i, k), U(i, k + 1));
      const double qt =
          k == nz - 1 ? U(i, k) : upwind(Wt, U(i, k - 1), U(i, k), U(i, k + 1), U(i, k + 2));
      const double div = (Vr - Vl) / g.dx + (Wt - Wb) / g.dz;
      adv_u[g.at(i, k)] = (Vr * qr - Vl * ql) / g.dx + (Wt * qt - Wb * qb) / g.dz - U(i, k) * div;
    }
    // z-momentum on the control volume of interior w-face (i, k).
#pragma omp parallel for schedule(static)
  for (int k = 1; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      // x-fluxes at corners (i, k) (left) and (i+1, k) (right)
      const double Vl = 0.5 * (U(i, k - 1) + U(i, k)), Vr = 0.5 * (U(i + 1, k - 1) + U(i + 1, k));
      const double ql = upwind(Vl, W(i - 2, k), W(i - 1, k), W(i, k), W(i + 1, k));
      const double qr = upwind(Vr, W(i - 1, k), W(i, k), W(i + 1, k), W(i + 2, k));
      // z-fluxes at cell centres k-1 (bottom) and k (top)
      const double Wb = 0.5 * (W(i, k - 1) + W(i, k)), Wt = 0.5 * (W(i, k) + W(i, k + 1));
      const double qb = upwind(Wb, W(i, k - 2), W(i, k - 1), W(i, k), W(i, k + 1));
      const double qt = upwind(Wt, W(i, k - 1), W(i, k), W(i, k + 1), W(i, k + 2));
      const double div = (Vr - Vl) / g.dx + (Wt - Wb) / g.dz;
      adv_w[g.at(i, k)] = (Vr * qr - Vl * ql) / g.dx + (Wt * qt - Wb * qb) / g.dz - W(i, k) * div;
    }
}

}  // namespace granbench::twod

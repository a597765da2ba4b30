// Densities and viscosities of the granular / light-fluid mixture.
//
// Density: rho = f rho_* phi + (1 - f) rho_l, with f averaged from the two cells of a face.
//
// Granular viscosity (Barker & Gray 2017):
//   I = 2 d |D| / sqrt(p / rho_*)                                         (2.8)
//   eta_g = mu(I) p / (2 |D|)                                             (2.11)
//   |D| = sqrt(D:D / 2) = sqrt((D_xx^2 + D_zz^2)/2 + D_xz^2)
// regularised as docs/design.md §8: p is clipped at 0 (eta_g = eta_min where p <= 0), |D| is
// floored at D_min and eta_g is kept in [eta_min, eta_max].
//
// Locations on the MAC grid: D_xx, D_zz are exact at cell centres and D_xz = gamma/2 with
// gamma = du/dz + dw/dx exact at corners. eta at a cell centre uses the corner gammas averaged
// to the centre (in the surface row of a graph surface, its two lower corners over the shear
// spacing: see there); eta at a corner uses the cell D_xx, D_zz averaged to the corner and p, f
// averaged from the surrounding cells (p extrapolated linearly to the bed, p = 0 on the top).
// Boundaries: no slip at the bed (ghost u = 2 u_bed - u, so gamma = 2 (u - u_bed)/dz; u_bed = 0
// unless the grid moves, grid.hpp), du/dz = 0 at the top
// (gamma = dw/dx there).
//
// Mixing in interface cells (Rheology::mixing, see parameters.hpp): arithmetic
// eta = f eta_g + (1-f) eta_l (default), or harmonic 1/eta = f/eta_g + (1-f)/eta_l (Gerris' main
// runs). f at a corner is the mean of its four cells.
// Tangent viscosities. The mu(I) stress tau = 2 eta(|D|, p) D has the tangent (consistent)
// modulus C = 2 eta [1 - (1 - Gamma/mu) D (x) D / (D:D)], Gamma = I mu'(I): along D it is the
// tangent viscosity eta Gamma/mu (~10 times smaller than eta in the §7 flow), across D the
// secant eta. The viscous step keeps the diagonal of C in its symmetric stencil: for the shear
// strain at a corner and the normal strain in a cell,
//   eta_n_tangent = eta_n [1 - (1 - Gamma/mu) D_xz^2 / |D|^2],
//   eta_c_tangent = eta_c [1 - (1 - Gamma/mu) (D_xx^2 + D_zz^2) / (2 |D|^2)],
// the two weights adding up to 1 for a divergence-free D. Both are >= eta Gamma/mu > 0.
// Rheology::interface_pressure = Extrapolated (parameters.hpp) instead evaluates eta_g in
// interface cells and at interface corners with the overburden pressure interpolated to the
// surface height of the columns, and treats an interface corner as granular below that height
// and as light fluid above it.
// Rheology::surface_row_shear_spacing (the default, with Extrapolated): the u of a partly filled
// surface row (fraction f) is the velocity of its grains, at their centroid (k + f/2) dz, not at
// the row's centre, so the shear rate at the granular corner below it is
// (u_k - u_{k-1}) / ((1 + f) dz / 2), not / dz. The corner's eta follows from that gamma, and
// eta and its tangent are scaled by 2 / (1 + f) so that the stencil's difference over dz gives
// the stress. The scale also multiplies the corner's dw/dx part of tau_xz (an approximation,
// small in a shallow wave). docs/twod-validation.md §4 has what it does to the growth rate.
// Threads: the grid loops are parallel over rows; each value is written once, by the same
// arithmetic for any thread count (parallel.hpp).
#include "twod/properties.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "twod/fill_fraction.hpp"
#include "twod/parallel.hpp"

namespace granbench::twod {

ViscosityModel::ViscosityModel(const Rheology& r)
    : r_(r),
      curve_(r.curve, r.material, r.h0_for_curve),
      d_over_sqrt_rho_(2.0 * r.material.d * std::sqrt(r.material.rho_star)) {}

double ViscosityModel::inertial_number(double p, double D) const {
  if (p <= 0.0) return std::numeric_limits<double>::infinity();
  return d_over_sqrt_rho_ * D / std::sqrt(p);  // (2.8): 2 d |D| / sqrt(p/rho_*)
}

double ViscosityModel::granular(double p, double D) const {
  return granular_with_tangent(p, D).eta;
}

GranularViscosity ViscosityModel::granular_with_tangent(double p, double D) const {
  if (r_.newtonian_eta > 0.0) return {r_.newtonian_eta, 1.0};
  if (p <= 0.0) return {r_.eta_min, 1.0};
  const double Df = std::max(D, r_.D_min);
  const double I = inertial_number(p, Df);
  const auto [mu, gamma_over_mu] = curve_.mu_with_log_slope(I);
  const double eta = mu * p / (2.0 * Df);  // (2.11)
  // eta does not follow |D| where |D| is floored or eta is capped or floored: tangent = secant
  if (D <= r_.D_min || eta <= r_.eta_min || eta >= r_.eta_max)
    return {std::clamp(eta, r_.eta_min, r_.eta_max), 1.0};
  return {eta, std::clamp(gamma_over_mu, 0.0, 1.0)};  // Gamma / mu = I mu'(I) / mu
}

double ViscosityModel::mix_tangent(double f, double eta_g, double eta_gt) const {
  if (f >= 1.0) return eta_gt;
  if (f <= 0.0) return r_.eta_light;
  if (r_.mixing == ViscosityMixing::Arithmetic) return f * eta_gt + (1.0 - f) * r_.eta_light;
  const double eta = mix(f, eta_g);  // d eta/d eta_g = f eta^2 / eta_g^2 of the harmonic mean
  return eta + f * eta * eta / (eta_g * eta_g) * (eta_gt - eta_g);
}

double ViscosityModel::mix(double f, double eta_g) const {
  if (f >= 1.0) return eta_g;
  if (f <= 0.0) return r_.eta_light;
  if (r_.mixing == ViscosityMixing::Arithmetic) return f * eta_g + (1.0 - f) * r_.eta_light;
  return 1.0 / (f / eta_g + (1.0 - f) / r_.eta_light);
}

void update_densities(const Grid& g, const std::vector<double>& f, const Rheology& r,
                      Properties& props) {
  const double rg = r.material.bulk_density(), rl = r.rho_light;
  auto rho = [&](double fr) { return fr * rg + (1.0 - fr) * rl; };
  parallel_for(g.nz, true, [&](int k) {
    for (int i = 0; i < g.nx; ++i)
      props.rho_u[g.at(i, k)] = rho(0.5 * (f[g.at(i - 1, k)] + f[g.at(i, k)]));
  });
  parallel_for(g.nz + 1, true, [&](int k) {
    for (int i = 0; i < g.nx; ++i) {
      const double fb = f[g.at(i, std::max(k - 1, 0))], ft = f[g.at(i, std::min(k, g.nz - 1))];
      props.rho_w[g.at(i, k)] = rho(0.5 * (fb + ft));
    }
  });
}

void update_viscosity(const Grid& g, const Fields& s, const std::vector<double>& p_eta,
                      const ViscosityModel& model, Properties& props) {
  const int nx = g.nx, nz = g.nz;
  const auto &u = s.u, &w = s.w, &p = p_eta, &f = s.f;
  const double eta_l = model.rheology().eta_light;
  // eta and its tangent for a mixture of fraction fr at pressure pr, the component having the
  // share `weight` of |D|^2
  auto set_eta = [&](double fr, double pr, double D, double weight, double& eta, double& eta_t) {
    if (fr <= 0.0) {  // mu(I) not needed
      eta = eta_t = eta_l;
      return;
    }
    const auto [eta_g, ratio] = model.granular_with_tangent(pr, D);
    const double eta_gt = eta_g * (1.0 - (1.0 - ratio) * weight);
    eta = model.mix(fr, eta_g);
    eta_t = model.mix_tangent(fr, eta_g, eta_gt);
  };
  auto share = [](double part, double D2) { return D2 > 0.0 ? std::min(part / D2, 1.0) : 0.0; };
  // gamma = du/dz + dw/dx at the corners, with the bed and top conditions.
  std::vector<double>& gam = props.gamma_n;
  gam.resize(g.corners());
  const double idx = 1.0 / g.dx, idz = 1.0 / g.dz;  // (divisions were a visible part of this)
  parallel_for(nz + 1, true, [&](int k) {
    for (int i = 0; i < nx; ++i) {
      const double dwdx = (w[g.at(i, k)] - w[g.at(i - 1, k)]) * idx;
      double dudz;
      if (k == 0)
        dudz = 2.0 * (u[g.at(i, 0)] - g.bed_velocity()) * idz;
      else if (k == nz)
        dudz = 0.0;
      else
        dudz = (u[g.at(i, k)] - u[g.at(i, k - 1)]) * idz;
      gam[g.at(i, k)] = dudz + dwdx;
    }
  });
  // Interface pressure (Rheology::interface_pressure): column heights and, per column, the
  // highest full cell below the surface.
  const bool extrapolate = model.rheology().interface_pressure == InterfacePressure::Extrapolated;
  std::vector<double>& hcol = props.column_height;
  if (extrapolate) {
    hcol.assign(nx, 0.0);
    // Each column sums over k in the serial order; the rows run outermost so that the inner loop
    // over i is contiguous and vectorises (column by column it strode through memory).
    parallel_for_ranges(nx, [&](int i0, int i1) {
      double* h = hcol.data();
      const double dz = g.dz;
      for (int k = 0; k < nz; ++k) {
        const double* fk = f.data() + std::size_t(k) * nx;
#pragma omp simd
        for (int i = i0; i < i1; ++i) h[i] += fk[i] * dz;
      }
    });
  }
  // Per column (cells: column i; corners: columns i-1 and i together), the nearest row at or
  // above k that is empty (nz if none) and the nearest at or below k that is full (-1 if none),
  // so that p_granular finds its rows without scanning: light-fluid cells holding wisps of
  // grains far above the surface scanned down through the whole layer, 9 % of a step.
  std::vector<int>&empty_above_c = props.empty_above_c, &full_below_c = props.full_below_c,
  &empty_above_n = props.empty_above_n, &full_below_n = props.full_below_n;
  if (extrapolate) {
    for (auto* v : {&empty_above_c, &full_below_c, &empty_above_n, &full_below_n})
      v->resize(std::size_t(nx) * nz);
    // Row by row (each row from the one below, or above), contiguous in i within a thread's
    // columns: a column-by-column scan strode through five arrays, 3 % of a 256 x 64 step.
    parallel_for_ranges(nx, [&](int i0, int i1) {
      auto row = [&](std::vector<int>& v, int k) { return v.data() + std::size_t(k) * nx; };
      // i = 0 takes its left neighbour across the periodic end; the rest run contiguously
      auto columns = [&](const double* fk, auto&& body) {
        if (i0 == 0) body(0, fk[nx - 1]);
#pragma omp simd
        for (int i = std::max(i0, 1); i < i1; ++i) body(i, fk[i - 1]);
      };
      for (int k = 0; k < nz; ++k) {  // upwards: the nearest full row at or below k
        const double* fk = f.data() + std::size_t(k) * nx;
        int *fc = row(full_below_c, k), *fn = row(full_below_n, k);
        const int *fc_below = row(full_below_c, std::max(k - 1, 0)),
                  *fn_below = row(full_below_n, std::max(k - 1, 0));
        const int none = -1;
        columns(fk, [&](int i, double left) {
          const int c_below = k > 0 ? fc_below[i] : none, n_below = k > 0 ? fn_below[i] : none;
          fc[i] = fk[i] == 1.0 ? k : c_below;
          fn[i] = left == 1.0 && fk[i] == 1.0 ? k : n_below;
        });
      }
      for (int k = nz - 1; k >= 0; --k) {  // downwards: the nearest empty row at or above k
        const double* fk = f.data() + std::size_t(k) * nx;
        int *ec = row(empty_above_c, k), *en = row(empty_above_n, k);
        const int *ec_above = row(empty_above_c, std::min(k + 1, nz - 1)),
                  *en_above = row(empty_above_n, std::min(k + 1, nz - 1));
        const int none = nz;
        columns(fk, [&](int i, double left) {
          const int c_above = k < nz - 1 ? ec_above[i] : none,
                    n_above = k < nz - 1 ? en_above[i] : none;
          ec[i] = fk[i] == 0.0 ? k : c_above;
          en[i] = left == 0.0 && fk[i] == 0.0 ? k : n_above;
        });
      }
    });
  }
  // p at height z in column i (or the mean of columns i-1, i when `corner`): linear between the
  // centre of the highest row below z whose cells are full and, at the surface height h, the
  // pressure p_s of the lowest light-fluid row above (its overburden; 0 if there is none).
  auto p_granular = [&](int i, double z, bool corner) {
    const double h = corner ? 0.5 * (hcol[g.wrap(i - 1)] + hcol[g.wrap(i)]) : hcol[g.wrap(i)];
    auto p_at = [&](int k) {
      return std::max(corner ? 0.5 * (p[g.at(i - 1, k)] + p[g.at(i, k)]) : p[g.at(i, k)], 0.0);
    };
    const auto& empty_above = corner ? empty_above_n : empty_above_c;
    const auto& full_below = corner ? full_below_n : full_below_c;
    int ka = std::max(int(std::floor(h / g.dz)), 0);  // lowest row entirely above the surface
    if (ka < nz) ka = empty_above[g.at(i, ka)];
    const double ps = ka < nz ? p_at(ka) : 0.0;
    if (z >= h) return ps;
    int kb = std::min(int(std::floor(z / g.dz - 0.5)), nz - 1);  // row with centre below z
    if (kb >= 0) kb = full_below[g.at(i, kb)];
    if (kb < 0) return ps;
    const double zb = g.zc(kb);
    if (zb >= h) return ps;
    return ps + (p_at(kb) - ps) * (h - z) / (h - zb);
  };
  // A partly filled cell with a full cell below and an empty one above: the surface row of a
  // surface that is a graph. Its strain rate is its grains': the shear of its two lower corners,
  // over the shear spacing (1 + f) dz / 2 as the corners' own stress takes it (below), not the
  // mean of all four corners, whose upper two lie in the light fluid. Averaged in, the light
  // fluid's shear set the surface row's viscosity: while gravity drove the light layer as a
  // stream (28 1/s at the surface, Rheology::ambient_pressure_gradient) it raised the 2 cm
  // growth by 0.1 1/s, and without the stream the mean of four corners halves the grains' shear
  // (docs/twod-validation.md §4, "Wisps at a face").
  const bool spacing = extrapolate && model.rheology().surface_row_shear_spacing;
  std::vector<double>&Dxx = props.D_xx_c, &Dzz = props.D_zz_c;
  Dxx.resize(g.cells());
  Dzz.resize(g.cells());
  // Rows spread over the threads (interleaved): mu(I) is evaluated only below the surface, so
  // contiguous blocks of rows gave one thread the grains and the other the light fluid.
  parallel_for_interleaved(nz, [&](int k) {
    for (int i = 0; i < nx; ++i) {
      const std::size_t c = g.at(i, k);
      Dxx[c] = (u[g.at(i + 1, k)] - u[c]) * idx;
      Dzz[c] = (w[g.at(i, k + 1)] - w[c]) * idz;
      double Dxz = 0.125 * (gam[g.at(i, k)] + gam[g.at(i + 1, k)] + gam[g.at(i, k + 1)] +
                            gam[g.at(i + 1, k + 1)]);
      if (spacing && is_graph_surface_row(g, f, i, k))  // the grains' shear: the corners below only
        Dxz = 0.25 * (gam[g.at(i, k)] + gam[g.at(i + 1, k)]) * 2.0 / (1.0 + f[c]);
      const double normal2 = 0.5 * (Dxx[c] * Dxx[c] + Dzz[c] * Dzz[c]);
      const double D = std::sqrt(normal2 + Dxz * Dxz);
      double pc = p[c];
      if (extrapolate && f[c] < 1.0 && f[c] > 0.0)  // at the centroid of the granular part
        pc = p_granular(i, k * g.dz + 0.5 * std::min(f[c] * g.dz, g.dz), false);
      set_eta(f[c], pc, D, share(normal2, D * D), props.eta_c[c], props.eta_c_tangent[c]);
      props.I_c[c] = model.inertial_number(p[c], D);
    }
  });
  // (corners read Dxx, Dzz of both neighbouring rows: after the cell loop has finished)
  parallel_for_interleaved(nz + 1, [&](int k) {
    const int kb = std::max(k - 1, 0), kt = std::min(k, nz - 1);
    for (int i = 0; i < nx; ++i) {
      const std::size_t a = g.at(i - 1, kb), b = g.at(i, kb), c = g.at(i - 1, kt), d = g.at(i, kt);
      const double dxx = 0.25 * (Dxx[a] + Dxx[b] + Dxx[c] + Dxx[d]);
      const double dzz = 0.25 * (Dzz[a] + Dzz[b] + Dzz[c] + Dzz[d]);
      const double dxz = 0.5 * gam[g.at(i, k)];
      const double D = std::sqrt(0.5 * (dxx * dxx + dzz * dzz) + dxz * dxz);
      const double shear_share = share(dxz * dxz, D * D);
      const std::size_t n = g.at(i, k);
      double pn;
      if (k == 0)  // linear extrapolation of the two lowest rows to the bed
        pn = 0.5 * (1.5 * (p[a] + p[b]) - 0.5 * (p[g.at(i - 1, 1)] + p[g.at(i, 1)]));
      else if (k == nz)
        pn = 0.0;  // p = 0 on the top boundary
      else
        pn = 0.25 * (p[a] + p[b] + p[c] + p[d]);
      const double fn = 0.25 * (f[a] + f[b] + f[c] + f[d]);
      if (extrapolate && k > 0 && k < nz && fn < 1.0 && fn > 0.0) {
        // an interface corner is granular when it lies below the surface of its two columns,
        // with the overburden pressure there; light fluid otherwise (no mixing)
        const double h = 0.5 * (hcol[g.wrap(i - 1)] + hcol[g.wrap(i)]);
        const double f_above = 0.5 * (f[c] + f[d]);
        if (model.rheology().surface_row_shear_spacing && k * g.dz < h && f_above < 1.0) {
          // below a partly filled row: gamma over the distance (1 + f) dz / 2 from the row
          // below's centre to the centroid of the row's grains, where its u lives; the corner
          // viscosity carries dz / that distance so that the stencil's gamma gives the stress
          const double scale = 2.0 / (1.0 + std::max(f_above, 0.0));
          const double dxz_s = dxz * scale;
          const double D_s = std::sqrt(0.5 * (dxx * dxx + dzz * dzz) + dxz_s * dxz_s);
          set_eta(1.0, p_granular(i, k * g.dz, true), D_s, share(dxz_s * dxz_s, D_s * D_s),
                  props.eta_n[n], props.eta_n_tangent[n]);
          props.eta_n[n] *= scale;
          props.eta_n_tangent[n] *= scale;
          continue;
        }
        set_eta(k * g.dz < h ? 1.0 : 0.0, p_granular(i, k * g.dz, true), D, shear_share,
                props.eta_n[n], props.eta_n_tangent[n]);
        continue;
      }
      set_eta(fn, pn, D, shear_share, props.eta_n[n], props.eta_n_tangent[n]);
    }
  });
}

}  // namespace granbench::twod

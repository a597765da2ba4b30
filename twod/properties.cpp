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
#include <array>
#include <cmath>
#include <limits>

#include "twod/fill_fraction.hpp"
#include "twod/parallel.hpp"
#include "twod/periodic_row.hpp"

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

void ViscosityModel::mixture_with_tangent_many(std::span<const double> f, std::span<const double> p,
                                               std::span<const double> D,
                                               std::span<const double> weight,
                                               std::span<double> eta,
                                               std::span<double> eta_tangent) const {
  // The arithmetic of granular_with_tangent, mix and mix_tangent, lane by lane: every branch is
  // computed and one result selected (the discarded lanes may hold inf or NaN), so each value is
  // bitwise the scalar one. std::max, std::min and std::clamp are written out as the library
  // defines them (std::max(a, b) = a < b ? b : a), so that even a NaN selects as there.
  constexpr std::size_t kChunk = 128;
  std::array<double, kChunk> I, mu, log_slope;
  const double eta_l = r_.eta_light, eta_min = r_.eta_min, eta_max = r_.eta_max, D_min = r_.D_min;
  const double newtonian = r_.newtonian_eta, scale = d_over_sqrt_rho_;
  const bool harmonic = r_.mixing == ViscosityMixing::Harmonic;
  for (std::size_t j0 = 0; j0 < f.size(); j0 += kChunk) {
    const std::size_t n = std::min(kChunk, f.size() - j0);
    const double *fj = f.data() + j0, *pj = p.data() + j0, *Dj = D.data() + j0,
                 *wj = weight.data() + j0;
    double *eta_j = eta.data() + j0, *eta_tj = eta_tangent.data() + j0;
    int granular = 0;  // a chunk of light fluid only (the corners above the surface) needs no mu(I)
    for (std::size_t j = 0; j < n; ++j) granular += fj[j] > 0.0;
    if (granular == 0) {
      std::fill_n(eta_j, n, eta_l);
      std::fill_n(eta_tj, n, eta_l);
      continue;
    }
#pragma omp simd
    for (std::size_t j = 0; j < n; ++j) {  // I of (2.8) at the floored |D|
      const double Df = Dj[j] < D_min ? D_min : Dj[j];
      I[j] = scale * Df / std::sqrt(pj[j]);
    }
    curve_.mu_with_log_slope_many(std::span(I.data(), n), std::span(mu.data(), n),
                                  std::span(log_slope.data(), n));
#pragma omp simd
    for (std::size_t j = 0; j < n; ++j) {
      const double fr = fj[j], pr = pj[j], Dv = Dj[j];
      const double Df = Dv < D_min ? D_min : Dv;
      // granular_with_tangent
      const double eta_mu = mu[j] * pr / (2.0 * Df);  // (2.11)
      const bool secant = Dv <= D_min || eta_mu <= eta_min || eta_mu >= eta_max;
      const double eta_clamped = eta_mu < eta_min ? eta_min : (eta_max < eta_mu ? eta_max : eta_mu);
      const double slope = log_slope[j] < 0.0 ? 0.0 : (1.0 < log_slope[j] ? 1.0 : log_slope[j]);
      double eta_g = secant ? eta_clamped : eta_mu, ratio = secant ? 1.0 : slope;
      if (pr <= 0.0) eta_g = eta_min, ratio = 1.0;
      if (newtonian > 0.0) eta_g = newtonian, ratio = 1.0;
      // set_eta: the tangent of the granular part, then the mixture
      const double eta_gt = eta_g * (1.0 - (1.0 - ratio) * wj[j]);
      double mixed, mixed_t;
      if (harmonic) {
        mixed = 1.0 / (fr / eta_g + (1.0 - fr) / eta_l);
        mixed_t = mixed + fr * mixed * mixed / (eta_g * eta_g) * (eta_gt - eta_g);
      } else {
        mixed = fr * eta_g + (1.0 - fr) * eta_l;
        mixed_t = fr * eta_gt + (1.0 - fr) * eta_l;
      }
      const bool full = fr >= 1.0, empty = fr <= 0.0;
      eta_j[j] = empty ? eta_l : (full ? eta_g : mixed);
      eta_tj[j] = empty ? eta_l : (full ? eta_gt : mixed_t);
    }
  }
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
      for (int k = 0; k < nz; ++k) {  // upwards: the nearest full row at or below k
        const double* fk = f.data() + std::size_t(k) * nx;
        int *fc = row(full_below_c, k), *fn = row(full_below_n, k);
        const int *fc_below = row(full_below_c, std::max(k - 1, 0)),
                  *fn_below = row(full_below_n, std::max(k - 1, 0));
        const int none = -1;
        for_columns_with_left(nx, i0, i1, [&](int il, int i) {
          const double left = fk[il];
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
        for_columns_with_left(nx, i0, i1, [&](int il, int i) {
          const double left = fk[il];
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
  // The pressure of every cell above its column's surface (z >= h in p_granular), once per column.
  std::vector<double>& p_above_surface = props.surface_pressure;
  if (extrapolate) {
    p_above_surface.resize(nx);
    for (int i = 0; i < nx; ++i) p_above_surface[i] = p_granular(i, hcol[i], false);
  }
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
  // One cell, as written in the equations. The rows below take every cell through the vectorised
  // path (the same arithmetic) but the interface cells at the surface under the Extrapolated
  // rule, which take this one.
  auto cell = [&](int i, int k) {
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
  };
  // Cell (i, k) takes the Extrapolated rule's interface treatment.
  auto interface_cell = [&](std::size_t c) { return extrapolate && f[c] < 1.0 && f[c] > 0.0; };
  // Rows in contiguous blocks per thread, whose sizes the team's balance sets by each block's
  // measured time (mu(I) is evaluated only below the surface, so equal blocks would give one
  // thread the grains and the other the light fluid; rows dealt out interleaved made both
  // threads write into every row's neighbours, which costs more on cores far apart than the
  // imbalance did: docs/performance.md, forty-sixth session). Each row goes in chunks: strain
  // rates, |D| and the shares of a chunk in one vectorised loop (`cell`'s expressions; its last
  // column wraps to column 0), then the viscosities of the chunk (mixture_with_tangent_many), then
  // the interface cells one by one. Scalar, cell by cell, this was 15 % of a one-thread 256 x 64
  // step.
  constexpr int kChunk = 128;
  const double* fd = f.data();
  parallel_for(nz, true, [&](int k) {
    const std::size_t row = std::size_t(k) * nx, above = row + nx;
    const double *ur = u.data() + row, *wr = w.data() + row, *wa = w.data() + above,
                 *pr = p.data() + row, *gr = gam.data() + row, *ga = gam.data() + above;
    double *dxx = Dxx.data() + row, *dzz = Dzz.data() + row, *I_c = props.I_c.data() + row;
    const double scale = model.inertial_number_prefactor();
    for (int i0 = 0; i0 < nx; i0 += kChunk) {
      const int n = std::min(kChunk, nx - i0);
      std::array<double, kChunk> D_chunk, weight_chunk;
      // (pointers by value: through a reference GCC reloads them after every store and gives up)
      double *D = D_chunk.data(), *weight = weight_chunk.data();
      auto strain = [=](int i, int ip) {  // column i, its right neighbour ip
        dxx[i] = (ur[ip] - ur[i]) * idx;
        dzz[i] = (wa[i] - wr[i]) * idz;
        const double Dxz = 0.125 * (gr[i] + gr[ip] + ga[i] + ga[ip]);
        const double normal2 = 0.5 * (dxx[i] * dxx[i] + dzz[i] * dzz[i]);
        const double Dv = std::sqrt(normal2 + Dxz * Dxz);
        const double D2 = Dv * Dv, part = normal2 / D2;
        D[i - i0] = Dv;
        weight[i - i0] = D2 > 0.0 ? (1.0 < part ? 1.0 : part) : 0.0;  // share()
        const double I = scale * Dv / std::sqrt(pr[i]);
        I_c[i] = pr[i] <= 0.0 ? std::numeric_limits<double>::infinity() : I;
      };
      const int wrap_end = i0 + n == nx ? i0 + n - 1 : i0 + n;  // the last column wraps
#pragma omp simd
      for (int i = i0; i < wrap_end; ++i) strain(i, i + 1);
      if (wrap_end < i0 + n) strain(nx - 1, 0);
      // The interface cells: those above their column's surface (most of them hold wisps of
      // grains in the light fluid) differ only in their pressure; the others, at the surface,
      // go through `cell` after the chunk.
      std::array<double, kChunk> pc_chunk;
      double* pc = pc_chunk.data();
      std::array<int, kChunk> at_surface;
      int surface_cells = 0;
      for (int i = i0; i < i0 + n; ++i) {
        pc[i - i0] = pr[i];
        if (!interface_cell(row + i)) continue;
        const double z = k * g.dz + 0.5 * std::min(fd[row + i] * g.dz, g.dz);  // as in `cell`
        if (z >= hcol[i] && !(spacing && is_graph_surface_row(g, f, i, k)))
          pc[i - i0] = p_above_surface[i];
        else
          at_surface[surface_cells++] = i;
      }
      model.mixture_with_tangent_many(std::span(fd + row + i0, n), std::span(pc, n),
                                      std::span(D, n), std::span(weight, n),
                                      std::span(props.eta_c.data() + row + i0, n),
                                      std::span(props.eta_c_tangent.data() + row + i0, n));
      for (int j = 0; j < surface_cells; ++j) cell(at_surface[j], k);
    }
  });
  // One corner, as `cell` is one cell.
  auto corner = [&](int i, int k) {
    const int kb = std::max(k - 1, 0), kt = std::min(k, nz - 1);
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
        return;
      }
      set_eta(k * g.dz < h ? 1.0 : 0.0, p_granular(i, k * g.dz, true), D, shear_share,
              props.eta_n[n], props.eta_n_tangent[n]);
      return;
    }
    set_eta(fn, pn, D, shear_share, props.eta_n[n], props.eta_n_tangent[n]);
  };
  // (corners read Dxx, Dzz of both neighbouring rows: after the cell loop has finished)
  // In chunks as the cells: `corner`'s expressions vectorised (its first column wraps to column
  // nx - 1), the interface corners of the Extrapolated rule one by one.
  parallel_for(nz + 1, true, [&](int k) {
    const int kb = std::max(k - 1, 0), kt = std::min(k, nz - 1);
    const std::size_t row_b = std::size_t(kb) * nx, row_t = std::size_t(kt) * nx,
                      row = std::size_t(k) * nx, row_1 = std::size_t(1) * nx;
    const double *xb = Dxx.data() + row_b, *xt = Dxx.data() + row_t, *zb = Dzz.data() + row_b,
                 *zt = Dzz.data() + row_t, *pb = p.data() + row_b, *pt = p.data() + row_t,
                 *p1 = p.data() + row_1, *fb = fd + row_b, *ft = fd + row_t, *gr = gam.data() + row;
    const bool bed = k == 0, top = k == nz;
    for (int i0 = 0; i0 < nx; i0 += kChunk) {
      const int n = std::min(kChunk, nx - i0);
      std::array<double, kChunk> D_chunk, weight_chunk, pn_chunk, fn_chunk;
      // (pointers by value: through a reference GCC reloads them after every store and gives up)
      double *D = D_chunk.data(), *weight = weight_chunk.data(), *pn = pn_chunk.data(),
             *fn = fn_chunk.data();
      auto inputs = [=](int im, int i) {  // corner column i, the cells' columns im = i - 1 and i
        const double dxx = 0.25 * (xb[im] + xb[i] + xt[im] + xt[i]);
        const double dzz = 0.25 * (zb[im] + zb[i] + zt[im] + zt[i]);
        const double dxz = 0.5 * gr[i];
        const double Dv = std::sqrt(0.5 * (dxx * dxx + dzz * dzz) + dxz * dxz);
        const double D2 = Dv * Dv, part = dxz * dxz / D2;
        D[i - i0] = Dv;
        weight[i - i0] = D2 > 0.0 ? (1.0 < part ? 1.0 : part) : 0.0;  // share()
        fn[i - i0] = 0.25 * (fb[im] + fb[i] + ft[im] + ft[i]);
      };
      // (corner columns i0 .. i0 + n - 1, column 0 wrapping; one loop per kind of row: GCC does
      // not vectorise a select on the row's kind)
      auto columns = [&](auto&& body) { for_columns_with_left(nx, i0, i0 + n, body); };
      columns(inputs);
      if (bed)  // linear extrapolation of the two lowest rows to the bed
        columns([=](int im, int i) {
          pn[i - i0] = 0.5 * (1.5 * (pb[im] + pb[i]) - 0.5 * (p1[im] + p1[i]));
        });
      else if (top)
        columns([=](int, int i) { pn[i - i0] = 0.0; });  // p = 0 on the top boundary
      else
        columns([=](int im, int i) { pn[i - i0] = 0.25 * (pb[im] + pb[i] + pt[im] + pt[i]); });
      // Interface corners above the surface of their two columns are light fluid (`corner`):
      // fraction 0. The others, at the surface, go through `corner` after the chunk.
      std::array<double, kChunk> fraction_chunk;
      double* fraction = fraction_chunk.data();
      std::array<int, kChunk> at_surface;
      int surface_corners = 0;
      const double z = k * g.dz;
      for (int i = i0; i < i0 + n; ++i) {
        const double fr = fn[i - i0];
        fraction[i - i0] = fr;
        if (!(extrapolate && !bed && !top && fr < 1.0 && fr > 0.0)) continue;
        const double h = 0.5 * (hcol[g.wrap(i - 1)] + hcol[i]);  // as in `corner`
        if (z < h)
          at_surface[surface_corners++] = i;
        else
          fraction[i - i0] = 0.0;
      }
      model.mixture_with_tangent_many(std::span(fraction, n), std::span(pn, n), std::span(D, n),
                                      std::span(weight, n),
                                      std::span(props.eta_n.data() + row + i0, n),
                                      std::span(props.eta_n_tangent.data() + row + i0, n));
      for (int j = 0; j < surface_corners; ++j) corner(at_surface[j], k);
    }
  });
}

}  // namespace granbench::twod

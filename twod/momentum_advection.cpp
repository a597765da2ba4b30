// The advective acceleration (u . grad) u of (2.10), explicit in time.
//
// On each staggered control volume (around a u-face or a w-face) the flux form
//   (u . grad) q = div(u q) - q div(u)
// is evaluated with the advecting velocity averaged to the control-volume faces and the
// advected component q reconstructed upwind with a van Leer-limited slope (second order where
// smooth, no new extrema; stable for the Courant numbers < 1/2 the VOF already imposes). The
// - q div(u) term removes the discrete divergence of the averaged advecting field.
//
// The consistent form (the solver's default) carries q with the mass fluxes G of the step's VOF
// advection instead of the velocity:  A = [div(G q) - q div(G)] / (rho^n - dt div(G)),  so that
// rho^{n+1} (u^n - dt A) = rho^n u^n - dt div(G q): the discrete momentum balance of the mass
// that the VOF step moved (Rudman 1997; Arrufat et al. 2021 on staggered grids). Its face values
// are centred in time: along the face's normal by the MUSCL-Hancock slope (upwind() below) and,
// with the transverse terms (SolverParams::advection_transverse_terms, the default), across it:
//   q_face = q_up + (1 - c)/2 dq_normal - (dt/2) V_t (dq/dt_t)_up  (donor-cell difference),
// V_t the velocity along the face at the upwind point (Colella 1990's corner transport, the
// transverse part of Bell, Colella & Glaz 1989's face values, without their force term: that
// term, approximated from the BDF2 memory, moved the 2 cm slow wave away from its limit).
// Without the transverse part the face value lags half a step in the direction along the face,
// a first-order error that travels with the wave over the grid (docs/twod-validation.md §10).
// "Upwind" is the side the face's carrier comes from: the mass flux's side in the consistent
// form. A staggered volume's face carries the average of two cells' mass fluxes, and at an
// overturned front the average of their velocities can point the other way (grains sinking
// through one half of the face, light fluid rising faster through the other). Upwinded by that
// velocity, the mass leaving a volume took its neighbour's momentum with it: an anti-diffusion
// that grew a face's speed by ~10 % per step to 54 m/s under a front of the paper's 12 cm
// rollwave at 48 cells per h0 (docs/twod-validation.md §11 item 9). In the velocity form the
// carrier is the velocity, so nothing changes there.
// Boundaries: no flux through the bed; at the top q is extended with zero gradient.
#include "twod/momentum_advection.hpp"

#include <algorithm>
#include <cmath>

#include "twod/parallel.hpp"

namespace granbench::twod {

namespace {
// (both sides computed, then one chosen: a loop of these has no branches and vectorises; the
// unchosen quotient may be 0/0, which is never used)
double van_leer(double a, double b) {
  const double mean = 2.0 * a * b / (a + b);
  return a * b > 0.0 ? mean : 0.0;
}

// Upwind-reconstructed face value between q1 (behind) and q2 (ahead) for carrier V, with q0
// before q1 and q3 after q2. With c = |V| dt / h > 0 the slope is taken at the middle of the
// step, (1 - c)/2 instead of 1/2 (MUSCL-Hancock, the advective part of BCG's face values): the
// one-step update of one-dimensional advection is then second order in time, without forward
// Euler's anti-diffusion (U^2 dt/2) d2/dx2.
double upwind(double V, double q0, double q1, double q2, double q3, double c = 0.0) {
  const double half = 0.5 * (1.0 - c);
  const double from_behind = q1 + half * van_leer(q1 - q0, q2 - q1);
  const double from_ahead = q2 - half * van_leer(q2 - q1, q3 - q2);
  return V >= 0.0 ? from_behind : from_ahead;
}

// What enters a control volume per unit area and time through its two faces along one
// direction (carriers at the lower and upper face); divided by the spacing, per unit volume.
double inflow(double lower, double upper) {
  return std::max(lower, 0.0) + std::max(-upper, 0.0);
}

// The flux form on both staggered control volumes. The carriers cx, cz (laid out like u and w)
// give what crosses x-face (i, k) and z-face (i, k) per unit area and time: the velocity itself
// (the velocity form) or the mass flux (the consistent form); the control volume's fluxes are
// their averages, upwinded by the averaged carrier (the averaged velocity sets only the Courant
// number of the time centring). Each value is
//   (sum of carrier q over the faces - q_P sum of carriers) / norm(P, sum of carriers, inflow).
// Two passes: the faces first (each control-volume face is shared by two volumes, so its carrier
// C and flux C q are computed once, into `faces`), then the volumes. The faces' stencils reach
// two cells along their direction; away from the periodic ends and from the bed and top they
// read the arrays directly, elsewhere through the wrapped and clamped indices (the same values;
// the direct reads save the index work). Each volume's value is the same arithmetic on the same
// numbers as when every volume reconstructed its own four faces, at half the reconstructions.
// Besides the momentum (q = u, w), the pass can carry a second field laid out like u and w
// (`carried`, the BDF2 step's memory in solver.cpp) with the same carriers, upwind sides and
// time centring, at the cost of its reconstructions only. Its values are bitwise those of a
// separate pass with q = that field.
template <bool Carry, class Norm>
void flux_form_pass(const Grid& g, const Fields& s, const std::vector<double>& cx,
                    const std::vector<double>& cz, Norm&& norm_u, Norm&& norm_w, double dt_centre,
                    AdvectionFaces& faces, std::vector<double>& adv_u, std::vector<double>& adv_w,
                    const CarriedField& carried, bool transverse_terms) {
  // Courant numbers of the time-centred face values (0: the plain upwind slope)
  const double cxr = dt_centre / g.dx, czr = dt_centre / g.dz;
  auto cx_of = [=](double V) { return std::abs(V) * cxr; };
  auto cz_of = [=](double V) { return std::abs(V) * czr; };
  const int nx = g.nx, nz = g.nz;
  const auto &u = s.u, &w = s.w;
  // The transverse terms: half a step of the transport along the face, -(dt/2) V_t dq/dt_t, with
  // V_t the velocity along the face at the upwind point and dq/dt_t the upwind difference along
  // V_t there (donor cell, as Colella's corner transport: the centred difference let a light
  // fluid ten times lighter than the default oscillate and diverge within 0.55 s of the
  // rollwave; rows clamped at the bed and top).
  const double half_dt = transverse_terms ? 0.5 * dt_centre : 0.0;
  const double idx_t = 1.0 / g.dx, idz_t = 1.0 / g.dz;
  auto donor = [](double V, double behind, double here, double ahead, double inv_h)
      __attribute__((always_inline)) {
    const double back = here - behind, forward = ahead - here;
    return (V >= 0.0 ? back : forward) * inv_h;
  };
  // the term for field Q at (i, k), transported by Vt along z or along x
  auto along_z = [=](auto&& Q, int i, int k, double Vt) __attribute__((always_inline)) {
    return half_dt * Vt * donor(Vt, Q(i, k - 1), Q(i, k), Q(i, k + 1), idz_t);
  };
  auto along_x = [=](auto&& Q, int i, int k, double Vt) __attribute__((always_inline)) {
    return half_dt * Vt * donor(Vt, Q(i - 1, k), Q(i, k), Q(i + 1, k), idx_t);
  };
  // (for Carry = false the carried field's accessors read u and w and are never used)
  const std::vector<double>& pu = Carry ? *carried.u : u;
  const std::vector<double>& pw = Carry ? *carried.w : w;
  // every u-face and interior w-face is written below; the bed and top w-faces carry no
  // momentum (no serial fill of the whole arrays: the other threads would wait through it)
  adv_u.resize(g.cells());
  adv_w.resize(g.w_faces());
  for (int i = 0; i < nx; ++i) adv_w[g.at(i, 0)] = adv_w[g.at(i, nz)] = 0.0;
  for (auto* v : {&faces.ux_c, &faces.ux_f, &faces.wz_c, &faces.wz_f}) v->resize(g.cells());
  for (auto* v : {&faces.uz_c, &faces.uz_f, &faces.wx_c, &faces.wx_f}) v->resize(g.w_faces());
  if constexpr (Carry) {
    carried.adv_u->resize(g.cells());
    carried.adv_w->resize(g.w_faces());
    for (int i = 0; i < nx; ++i) (*carried.adv_w)[g.at(i, 0)] = (*carried.adv_w)[g.at(i, nz)] = 0.0;
    for (auto* v : {&faces.ux_p, &faces.wz_p}) v->resize(g.cells());
    for (auto* v : {&faces.uz_p, &faces.wx_p}) v->resize(g.w_faces());
  }
  // The face arrays as pointers: loaded once, not through `faces` at every face (which kept
  // the face loops from vectorising).
  double *const ux_c = faces.ux_c.data(), *const ux_f = faces.ux_f.data(),
                *const uz_c = faces.uz_c.data(), *const uz_f = faces.uz_f.data(),
                *const wx_c = faces.wx_c.data(), *const wx_f = faces.wx_f.data(),
                *const wz_c = faces.wz_c.data(), *const wz_f = faces.wz_f.data();
  double *const ux_p = Carry ? faces.ux_p.data() : nullptr,
                *const uz_p = Carry ? faces.uz_p.data() : nullptr,
                *const wx_p = Carry ? faces.wx_p.data() : nullptr,
                *const wz_p = Carry ? faces.wz_p.data() : nullptr;
  // Accessors: q(i, k) for the u-rows (clamped to 0..nz-1) and the w-rows (0..nz), periodic in i.
  auto wrapped = [&](const std::vector<double>& q, int top) {
    return [ q = q.data(), &g, top ](int i, int k) __attribute__((always_inline)) {
      return q[g.at(i, std::clamp(k, 0, top))];
    };
  };
  auto direct = [nx](const std::vector<double>& q) {
    return [ q = q.data(), nx ](int i, int k) __attribute__((always_inline)) {
      return q[std::size_t(k) * nx + i];
    };
  };
  // Row k of faces: `body(i, k, U, W, PU, PW, CX, CZ)` (PU, PW: the carried field) with direct
  // reads for i in [2, nx - 2) when `inside` (the stencil stays within the rows), wrapped and
  // clamped reads elsewhere.
  auto row = [&](auto&& body, int k, bool inside) {
    const auto Uw = wrapped(u, nz - 1), Ww = wrapped(w, nz), PUw = wrapped(pu, nz - 1),
               PWw = wrapped(pw, nz), CXw = wrapped(cx, nz - 1), CZw = wrapped(cz, nz);
    if (!inside || nx <= 4) {
      for (int i = 0; i < nx; ++i) body(i, k, Uw, Ww, PUw, PWw, CXw, CZw);
      return;
    }
    const auto Ud = direct(u), Wd = direct(w), PUd = direct(pu), PWd = direct(pw), CXd = direct(cx),
               CZd = direct(cz);
    for (int i = 0; i < 2; ++i) body(i, k, Uw, Ww, PUw, PWw, CXw, CZw);
    // Vectorised: each face writes only its own entries and reads only the inputs, and its
    // branches are selections between values both computed, so every lane does the scalar
    // arithmetic and the results are bitwise those of the scalar loop. (`local`: a copy of the
    // body whose captures the compiler can keep in registers across the loop.)
    const auto local = body;
#pragma omp simd
    for (int i = 2; i < nx - 2; ++i) local(i, k, Ud, Wd, PUd, PWd, CXd, CZd);
    for (int i = nx - 2; i < nx; ++i) body(i, k, Uw, Ww, PUw, PWw, CXw, CZw);
  };
  // The u-volumes' x-face at cell centre (i, k), between u-faces i and i + 1.
  auto u_x_face = [=](int i, int k, auto&& U, auto&& W, auto&& PU, auto&&, auto&& CX, auto&&) {
    const double V = 0.5 * (U(i, k) + U(i + 1, k)), C = 0.5 * (CX(i, k) + CX(i + 1, k));
    const std::size_t f = std::size_t(k) * nx + i;
    ux_c[f] = C;
    double tq = 0.0, tp = 0.0;
    if (half_dt > 0.0) {  // at the upwind u-face, i or i + 1 (both evaluated, one chosen)
      auto Wt = [&](int iu) {
        return 0.25 * (W(iu - 1, k) + W(iu, k) + W(iu - 1, k + 1) + W(iu, k + 1));
      };
      const double Wl = Wt(i), Wr = Wt(i + 1);
      const double tq_l = along_z(U, i, k, Wl), tq_r = along_z(U, i + 1, k, Wr);
      tq = C >= 0.0 ? tq_l : tq_r;
      if constexpr (Carry) {
        const double tp_l = along_z(PU, i, k, Wl), tp_r = along_z(PU, i + 1, k, Wr);
        tp = C >= 0.0 ? tp_l : tp_r;
      }
    }
    ux_f[f] = C * (upwind(C, U(i - 1, k), U(i, k), U(i + 1, k), U(i + 2, k), cx_of(V)) - tq);
    if constexpr (Carry)
      ux_p[f] = C * (upwind(C, PU(i - 1, k), PU(i, k), PU(i + 1, k), PU(i + 2, k), cx_of(V)) - tp);
  };
  // The u-volumes' z-face at corner (i, k), k = 1 .. nz (none through the bed, k = 0: below); at
  // the top q is extended with zero gradient.
  auto u_z_face = [=](int i, int k, auto&& U, auto&& W, auto&& PU, auto&&, auto&&, auto&& CZ) {
    const std::size_t f = std::size_t(k) * nx + i;
    const double V = 0.5 * (W(i - 1, k) + W(i, k)), C = 0.5 * (CZ(i - 1, k) + CZ(i, k));
    auto face_value = [&](auto&& Q) {
      return k == nz ? Q(i, k - 1)
                     : upwind(C, Q(i, k - 2), Q(i, k - 1), Q(i, k), Q(i, k + 1), cz_of(V));
    };
    double tq = 0.0, tp = 0.0;
    if (half_dt > 0.0 && k < nz) {  // at the upwind u-row, k - 1 or k (both, one chosen)
      const double Ub = U(i, k - 1), Ua = U(i, k);
      const double tq_b = along_x(U, i, k - 1, Ub), tq_a = along_x(U, i, k, Ua);
      tq = C >= 0.0 ? tq_b : tq_a;
      if constexpr (Carry) {
        const double tp_b = along_x(PU, i, k - 1, Ub), tp_a = along_x(PU, i, k, Ua);
        tp = C >= 0.0 ? tp_b : tp_a;
      }
    }
    uz_c[f] = C;
    uz_f[f] = C * (face_value(U) - tq);
    if constexpr (Carry) uz_p[f] = C * (face_value(PU) - tp);
  };
  // The w-volumes' x-face at corner (i, k), k = 1 .. nz - 1.
  auto w_x_face = [=](int i, int k, auto&& U, auto&& W, auto&&, auto&& PW, auto&& CX, auto&&) {
    const double V = 0.5 * (U(i, k - 1) + U(i, k)), C = 0.5 * (CX(i, k - 1) + CX(i, k));
    const std::size_t f = std::size_t(k) * nx + i;
    wx_c[f] = C;
    double tq = 0.0, tp = 0.0;
    if (half_dt > 0.0) {  // at the upwind w-face, i - 1 or i (both evaluated, one chosen)
      const double Wl = W(i - 1, k), Wr = W(i, k);
      const double tq_l = along_z(W, i - 1, k, Wl), tq_r = along_z(W, i, k, Wr);
      tq = C >= 0.0 ? tq_l : tq_r;
      if constexpr (Carry) {
        const double tp_l = along_z(PW, i - 1, k, Wl), tp_r = along_z(PW, i, k, Wr);
        tp = C >= 0.0 ? tp_l : tp_r;
      }
    }
    wx_f[f] = C * (upwind(C, W(i - 2, k), W(i - 1, k), W(i, k), W(i + 1, k), cx_of(V)) - tq);
    if constexpr (Carry)
      wx_p[f] = C * (upwind(C, PW(i - 2, k), PW(i - 1, k), PW(i, k), PW(i + 1, k), cx_of(V)) - tp);
  };
  // The w-volumes' z-face at cell centre (i, k), between w-faces k and k + 1.
  auto w_z_face = [=](int i, int k, auto&& U, auto&& W, auto&&, auto&& PW, auto&&, auto&& CZ) {
    const double V = 0.5 * (W(i, k) + W(i, k + 1)), C = 0.5 * (CZ(i, k) + CZ(i, k + 1));
    const std::size_t f = std::size_t(k) * nx + i;
    wz_c[f] = C;
    double tq = 0.0, tp = 0.0;
    if (half_dt > 0.0) {  // at the upwind w-face, k or k + 1 (both evaluated, one chosen)
      auto Ut = [&](int ku) {
        return 0.25 * (U(i, ku - 1) + U(i + 1, ku - 1) + U(i, ku) + U(i + 1, ku));
      };
      const double Ub = Ut(k), Ua = Ut(k + 1);
      const double tq_b = along_x(W, i, k, Ub), tq_a = along_x(W, i, k + 1, Ua);
      tq = C >= 0.0 ? tq_b : tq_a;
      if constexpr (Carry) {
        const double tp_b = along_x(PW, i, k, Ub), tp_a = along_x(PW, i, k + 1, Ua);
        tp = C >= 0.0 ? tp_b : tp_a;
      }
    }
    wz_f[f] = C * (upwind(C, W(i, k - 1), W(i, k), W(i, k + 1), W(i, k + 2), cz_of(V)) - tq);
    if constexpr (Carry)
      wz_p[f] = C * (upwind(C, PW(i, k - 1), PW(i, k), PW(i, k + 1), PW(i, k + 2), cz_of(V)) - tp);
  };
  // (rows in parallel: each entry is written once; parallel.hpp)
  parallel_for(nz + 1, true, [&](int k) {
    if (k < nz) row(u_x_face, k, k >= 1 && k + 1 < nz);  // (the transverse reads k +- 1)
    if (k > 0) {
      row(u_z_face, k, k >= 2 && k + 1 <= nz - 1);
    } else {
      for (int i = 0; i < nx; ++i) {
        uz_c[i] = uz_f[i] = 0.0;
        if constexpr (Carry) uz_p[i] = 0.0;
      }
    }
    if (k > 0 && k < nz) row(w_x_face, k, true);
    if (k < nz) row(w_z_face, k, k >= 1 && k + 2 <= nz);
  });
  // The volumes, from their faces (left/right, bottom/top).
  // (multiplied by the inverse spacings: six divisions per volume were most of this pass's time)
  const double idx = 1.0 / g.dx, idz = 1.0 / g.dz;
  // the volume's carrier divergence and normalisation, shared by the momentum and the carried
  // field: (flux - q div) / norm
  struct Balance {
    double div, norm;
  };
  auto balance = [&](double Cl, double Cr, double Cb, double Ct, std::size_t c, auto&& norm) {
    const double div = (Cr - Cl) * idx + (Ct - Cb) * idz;
    const double in = inflow(Cl, Cr) * idx + inflow(Cb, Ct) * idz;
    return Balance{div, norm(c, div, in)};
  };
  auto value = [&](const Balance& b, double Fl, double Fr, double Fb, double Ft, double q) {
    const double flux = (Fr - Fl) * idx + (Ft - Fb) * idz;
    return (flux - q * b.div) / b.norm;
  };
  // Volume c from its faces, with l (u) or r (w) the index of its neighbour along x: the first u-
  // and the last w-volume of a row take theirs across the periodic end, on their own; the others
  // run in a loop that vectorises (`omp simd`, as the faces above).
  double *const adv_u_p = adv_u.data(), *const adv_w_p = adv_w.data();
  double* const carried_u_p = Carry ? carried.adv_u->data() : nullptr;
  double* const carried_w_p = Carry ? carried.adv_w->data() : nullptr;
  const double *const u_p = u.data(), *const w_p = w.data(), *const pu_p = pu.data(),
                      *const pw_p = pw.data();
  auto u_volume = [&](std::size_t c, std::size_t l) __attribute__((always_inline)) {
    const Balance b = balance(ux_c[l], ux_c[c], uz_c[c], uz_c[c + nx], c, norm_u);
    adv_u_p[c] = value(b, ux_f[l], ux_f[c], uz_f[c], uz_f[c + nx], u_p[c]);
    if constexpr (Carry)
      carried_u_p[c] = value(b, ux_p[l], ux_p[c], uz_p[c], uz_p[c + nx], pu_p[c]);
  };
  auto w_volume = [&](std::size_t c, std::size_t r) __attribute__((always_inline)) {
    const Balance b = balance(wx_c[c], wx_c[r], wz_c[c - nx], wz_c[c], c, norm_w);
    adv_w_p[c] = value(b, wx_f[c], wx_f[r], wz_f[c - nx], wz_f[c], w_p[c]);
    if constexpr (Carry)
      carried_w_p[c] = value(b, wx_p[c], wx_p[r], wz_p[c - nx], wz_p[c], pw_p[c]);
  };
  parallel_for(nz, true, [&](int k) {
    const std::size_t first = std::size_t(k) * nx;
    u_volume(first, first + nx - 1);
#pragma omp simd
    for (std::size_t c = first + 1; c < first + nx; ++c) u_volume(c, c - 1);
  });
  parallel_for(nz - 1, true, [&](int k_from_1) {
    const std::size_t first = std::size_t(k_from_1 + 1) * nx, last = first + nx - 1;
#pragma omp simd
    for (std::size_t c = first; c < last; ++c) w_volume(c, c + 1);
    w_volume(last, first);
  });
}

// The flux form with or without a carried field.
template <class Norm>
void flux_form(const Grid& g, const Fields& s, const std::vector<double>& cx,
               const std::vector<double>& cz, Norm&& norm_u, Norm&& norm_w, double dt_centre,
               AdvectionFaces& faces, std::vector<double>& adv_u, std::vector<double>& adv_w,
               const CarriedField& carried, bool transverse_terms) {
  if (carried.u)
    flux_form_pass<true>(g, s, cx, cz, norm_u, norm_w, dt_centre, faces, adv_u, adv_w, carried,
                         transverse_terms);
  else
    flux_form_pass<false>(g, s, cx, cz, norm_u, norm_w, dt_centre, faces, adv_u, adv_w, carried,
                          transverse_terms);
}
}  // namespace

void momentum_advection(const Grid& g, const Fields& s, AdvectionFaces& faces,
                        std::vector<double>& adv_u, std::vector<double>& adv_w,
                        const CarriedField& carried) {
  auto unit = [](std::size_t, double, double) { return 1.0; };
  flux_form(g, s, s.u, s.w, unit, unit, 0.0, faces, adv_u, adv_w, carried, false);
}

void mass_fluxes(const Grid& g, const Fields& s, const GrainFluxes& grains, double rho_g,
                 double rho_l, double dt, MassFluxes& m) {
  m.x.resize(g.cells());
  m.z.resize(g.w_faces());
  const double gx = (rho_g - rho_l) * g.dx / dt, gz = (rho_g - rho_l) * g.dz / dt;
  const long nx = long(m.x.size()), nz = long(m.z.size());
  parallel_for_ranges(nx, [&](int begin, int end) {
    for (int c = begin; c < end; ++c) m.x[c] = rho_l * s.u[c] + gx * grains.x[c];
  });
  parallel_for_ranges(nz, [&](int begin, int end) {
    for (int c = begin; c < end; ++c) m.z[c] = rho_l * s.w[c] + gz * grains.z[c];
  });
}

void consistent_momentum_advection(const Grid& g, const Fields& s, const MassFluxes& m,
                                   const std::vector<double>& rho_u,
                                   const std::vector<double>& rho_w, double dt,
                                   AdvectionFaces& faces, std::vector<double>& adv_u,
                                   std::vector<double>& adv_w, const CarriedField& carried,
                                   bool transverse_terms) {
  // rho_new = rho^n - dt div(G): the density that the same mass fluxes leave in the control
  // volume, so that the update of rho u is a weighted mean of u^n and the incoming u's. The
  // staggered volume's fluxes are averages of the cells' fluxes, not a partition of its own
  // mass, so a volume that loses grains can be left with a rho_new far below what it lost (or
  // below zero): there the divisor is rho^n, or the mass that entered, whichever is larger, which
  // keeps the update a weighted mean (u^n plus at most the whole difference to the inflow).
  auto new_density = [&](const std::vector<double>& rho) {
    return [rho = rho.data(), dt](std::size_t c, double div, double in) {
      return std::max({rho[c] - dt * div, rho[c], dt * in});
    };
  };
  flux_form(g, s, m.x, m.z, new_density(rho_u), new_density(rho_w), dt, faces, adv_u, adv_w,
            carried, transverse_terms);
}

}  // namespace granbench::twod

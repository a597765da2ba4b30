// The horizontal pressure force on the grains of a partly filled surface row.
//
// In a cell holding the surface (granular fraction f, full cells below, empty above), the
// projection's hydrostatic balance (gravity and grad p on the same faces, with face densities
// from the face average of f) puts the cell-centre pressure at the centroid of its grains:
//
//   p_k = rho_g g cos(zeta) f dz / 2,      while full cells hold p = rho_g g cos(zeta) (h - z_c).
//
// So p_k follows the surface with half its slope, and the standard force on the surface row's
// u-face, -dz (p_{i,k} - p_{i-1,k}) = -rho_g g cos(zeta) dz dh / 2, is not the force on the grains
// the face holds, -f dz rho_g g cos(zeta) dh. Divided by the face's mass f rho_g dx dz, the row is
// driven by the surface slope 1/(2f) times too hard: twice at f = 1/4, two thirds at f = 3/4, and
// exactly only with the surface mid-cell. That is a first-order error in dz whose sign depends on
// where the surface sits in its cell, and the 2D growth rate followed it (docs/twod-validation.md
// §4).
//
// The correction replaces, on every u-face, the force of the discrete hydrostatic pressure P
// (integrated down from p = 0 at the top with the projection's face densities) by the force of
// the hydrostatic pressure of the grains where they actually sit in the face's row, both
// integrated over the face's height [k dz, (k+1) dz]:
//
//   F_face = -int_row (p_i(z) - p_{i-1}(z)) dz,   p_i(z) = g cos(zeta) int_z^Lz rho_i(z') dz'.
//
// With rho = rho_l + (rho_g - rho_l) phi (phi the grain indicator) the light fluid's share and
// the weight of the rows above cancel between exact and discrete (P_k carries the rows above
// exactly, and half of its own cell's grains), and what is left per column is the first moment
// of the row's own grains about the cell centre z_c:
//
//   int_row (p_exact - P) dz = (rho_g - rho_l) g cos(zeta) f dz (z_g - z_c),
//
// z_g the centroid height of the grains in the cell. For grains lying at the bottom of the cell
// (a surface with full cells below and empty above), z_g - z_c = -(1 - f) dz / 2; lying at its
// top (the underside of an overhang) +(1 - f) dz / 2. Which of the two is told by the cells above
// and below, s = f_{k-1} - f_{k+1} in [-1, 1] (1 at a surface that is a graph h(x); 0 for a wisp
// or droplet with nothing around, which keeps the standard force), so
//
//   correction_{i,k} = (rho_g - rho_l) g cos(zeta) (dz^2 / 2) [m_i - m_{i-1}],
//   m = s f (1 - f),
//
// (the bed counts as full, the open top as empty). For a graph surface whose two columns share
// the row (f_i dz = h_i - k dz) this is exactly the hydrostatic force on the face's grains,
// -(rho_g - rho_l) g cos(zeta) f_face dz (h_i - h_{i-1}); where the surface crosses a face between
// the columns it is the integral of the two columns' hydrostatic pressures over the face.
//
// Why local. An earlier form took the exact force from the column heights h = sum f dz,
// -(rho_g - rho_l) g cos(zeta) f_face dz (h_i - h_{i-1}), on every partly filled face. That
// assumes a surface that is a graph with both columns' surfaces in the face's row. At a steep
// front (a step of several cells) it spread the step's force evenly over the rows, which pushed
// the top of the front forward and its foot back; under the overhang that followed, it took away
// from near-empty light-fluid faces (mass ~rho_l dx dz) a pressure force that the actual pressure
// balanced, so they were driven at ~10^3-10^4 m/s^2. The coarse nonlinear rollwave (64 x 16,
// a0 = 0.2 mm) then sprayed grains to the top of the domain and diverged at 0.44 s
// (docs/twod-validation.md §4). The present form depends on the face's row and its neighbours
// only, is a smooth function of f (zero on full and empty cells), and needs no graph.
#include "twod/surface_row_pressure.hpp"

#include <algorithm>
#include <cmath>

#include "twod/parallel.hpp"
#include "twod/periodic_row.hpp"

namespace granbench::twod {

void surface_row_pressure_correction(const Grid& g, const SolverParams& params,
                                     const std::vector<double>& f,
                                     std::vector<double>& correction) {
  const double g_cos = params.rheology.material.g * std::cos(params.zeta);
  const double drho = params.rheology.material.bulk_density() - params.rheology.rho_light;
  const double scale = drho * g_cos * 0.5 * g.dz * g.dz;
  correction.resize(g.cells());
  const int nx = g.nx, nz = g.nz;
  parallel_for(nz, true, [&](int k) {  // rows in parallel, each entry written once
    const double* fc = f.data() + std::size_t(k) * nx;
    double* out = correction.data() + std::size_t(k) * nx;
    // m = s f (1 - f): the grains' first moment about the cell centre, in units of -dz/2 (a few
    // flops: evaluated for both cells of each face rather than stored). `below` and `above`
    // give the neighbouring rows' f; s is std::clamp(below - above, -1, 1) written out.
    auto row = [&](auto below, auto above) {
      auto m = [=](int i) {
        const double v = fc[i], d = below(i) - above(i);
        return (d < -1.0 ? -1.0 : (1.0 < d ? 1.0 : d)) * v * (1.0 - v);
      };
      for_columns_with_left(nx, 0, nx, [=](int il, int i) { out[i] = scale * (m(i) - m(il)); });
    };
    // (one loop per kind of row: GCC does not vectorise a select on the row's kind)
    const double *fb = k > 0 ? fc - nx : fc, *fa = k + 1 < nz ? fc + nx : fc;
    auto full = [](int) { return 1.0; };   // the bed counts as full
    auto empty = [](int) { return 0.0; };  // the open top as empty
    auto row_below = [=](int i) { return fb[i]; };
    auto row_above = [=](int i) { return fa[i]; };
    if (k == 0 && k + 1 == nz)
      row(full, empty);
    else if (k == 0)
      row(full, row_above);
    else if (k + 1 == nz)
      row(row_below, empty);
    else
      row(row_below, row_above);
  });
}

}  // namespace granbench::twod

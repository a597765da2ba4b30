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
// The correction replaces, on every u-face, the standard force of the discrete hydrostatic
// pressure by the exact hydrostatic force on the face's control volume:
//
//   exact     -(rho_g - rho_l) g cos(zeta) (h_i - h_{i-1}) f_face dz    (p_hs of two layers,
//             d p_hs / dx = (rho_g - rho_l) g cos(zeta) dh/dx below the surface, 0 above;
//             f_face dz of the face's height is below it)
//   standard  -dz (P_{i,k} - P_{i-1,k}),  P the discrete hydrostatic pressure of each column,
//             integrated down from p = 0 at the top with the projection's face densities.
//
// Both depend on f and the column heights h = sum f dz only, continuously, so the correction
// varies smoothly as the surface crosses a face, and it vanishes on full and empty faces (the
// discrete hydrostatic pressure is exact in full cells). The dynamic pressure keeps the standard
// force, and the projection is unchanged (its increment keeps the standard gradient). An earlier
// form took the correction from the actual pressure of the rows above and below; it jumped when
// the surface crossed a face and made the Picard passes stop converging.
#include "twod/surface_row_pressure.hpp"

#include <cmath>

namespace granbench::twod {

std::vector<double> surface_row_pressure_correction(const Grid& g, const SolverParams& params,
                                                    const std::vector<double>& f,
                                                    const std::vector<double>& h) {
  const double g_cos = params.rheology.material.g * std::cos(params.zeta);
  const double rho_g = params.rheology.material.bulk_density(), rho_l = params.rheology.rho_light;
  auto rho = [&](double fr) { return fr * rho_g + (1.0 - fr) * rho_l; };
  // the discrete hydrostatic pressure of each column (the projection's balance, properties.cpp's
  // face densities): half a cell below the top at the top face's density, then one face a cell
  std::vector<double> P(g.cells());
  for (int i = 0; i < g.nx; ++i) {
    double pk = g_cos * rho(f[g.at(i, g.nz - 1)]) * 0.5 * g.dz;
    P[g.at(i, g.nz - 1)] = pk;
    for (int k = g.nz - 1; k > 0; --k) {
      pk += g_cos * rho(0.5 * (f[g.at(i, k - 1)] + f[g.at(i, k)])) * g.dz;
      P[g.at(i, k - 1)] = pk;
    }
  }
  std::vector<double> correction(g.cells(), 0.0);
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const double f_face = 0.5 * (f[g.at(i - 1, k)] + f[g.at(i, k)]);
      if (!(f_face > 0.0 && f_face < 1.0)) continue;  // zero to round-off there anyway
      const double exact = -(rho_g - rho_l) * g_cos * (h[i] - h[g.wrap(i - 1)]) * f_face * g.dz;
      const double standard = -g.dz * (P[g.at(i, k)] - P[g.at(i - 1, k)]);
      correction[g.at(i, k)] = exact - standard;
    }
  return correction;
}

}  // namespace granbench::twod

// The shear-stress force on the w-faces around a partly filled surface row.
//
// The w-face between rows k-1 and k carries the vertical momentum of the control volume between
// the two cell centres, and the MAC stencil gives it the x-derivative of the corner shear stress
// over that whole height:  dz (tau_xz(i+1, k) - tau_xz(i, k)).
// Where row k holds the surface (fraction f, full cells below, empty above), the projection's
// hydrostatic balance with the face densities (1 + f)/2 rho_g puts the surface cell's pressure at
// the centroid of its grains (surface_row_pressure.cpp), so that face's control volume is, for the
// pressure, the span from the centre of row k-1 to that centroid, (1 + f) dz / 2, and the grains
// above the centroid, f dz / 2, belong to the w-face above (k+1), whose corners lie in the light
// fluid and carry no granular stress. The stencil thus integrates d tau_xz/dx over dz where the
// grains span (1 + f) dz / 2 below the centroid and f dz / 2 above it: (f - 1/2) dz too little in
// all. In a wave the crest's extra weight makes d tau_xz/dx = i k mu rho g cos(zeta) h' nearly
// uniform in depth near the surface, so the pressure below the surface row carried a uniform
// offset proportional to (f - 1/2) i h', in quadrature with the surface: measured against the exact
// eigenfunction (160 x 64, 8 cm), -28 i h' Pa/m with the surface at 0.1 of its cell and +28 i h'
// at 0.9, the prediction being 27.5. Its x-gradient acts on the whole layer like a force in phase
// with h, and the growth rate fell across the cell (docs/twod-validation.md §4).
//
// The correction moves the share to where the grains are, with the stress derivative of the
// corner below the surface row (the only granular one):
//   w-face k:     -(1 - f)/2 dz (tau(i+1, k) - tau(i, k)),
//   w-face k + 1:  + f/2     dz (tau(i+1, k) - tau(i, k)),
// tau = eta_n gamma_n, the stress of the corner as the stencil forms it (the shear spacing of a
// partly filled row is folded into eta_n: properties.cpp). Columns whose surface row is not a
// graph (a cell above holding grains, a cell below not full) are left alone, and so is a flat
// layer (tau the same in every column): the steady state does not change. Full and empty are
// judged up to the VOF's round-off (fill_fraction.hpp): with the surface on a cell face the VOF
// leaves wisps of 1e-22 above the films at the crests, and an exact test took every column for a
// non-graph one, so the correction acted nowhere there (docs/twod-validation.md §4).
#include "twod/surface_row_shear.hpp"

#include "twod/fill_fraction.hpp"
#include "twod/parallel.hpp"

namespace granbench::twod {

void surface_row_shear_correction(const Grid& g, const std::vector<double>& f,
                                  const Properties& props, std::vector<double>& correction) {
  correction.resize(g.w_faces());
  parallel_for_ranges(int(correction.size()), [&](int begin, int end) {
    for (int n = begin; n < end; ++n) correction[n] = 0.0;
  });
  const int nz = g.nz;
  // each column writes only its own w-faces
  parallel_for(g.nx, true, [&](int i) {
    for (int k = 1; k < nz - 1; ++k) {
      if (!is_graph_surface_row(g, f, i, k)) continue;
      const double fk = f[g.at(i, k)];
      const double dtau = props.eta_n[g.at(i + 1, k)] * props.gamma_n[g.at(i + 1, k)] -
                          props.eta_n[g.at(i, k)] * props.gamma_n[g.at(i, k)];
      correction[g.at(i, k)] = -0.5 * (1.0 - fk) * g.dz * dtau;
      correction[g.at(i, k + 1)] = 0.5 * fk * g.dz * dtau;
    }
  });
}

}  // namespace granbench::twod

// The staggered (MAC) grid of the 2D solver: nx x nz uniform cells on [0, Lx] x [0, Lz] in
// slope-aligned coordinates (x downslope, z normal to the bed), periodic in x. Cells may be
// anisotropic (dx != dz): roll waves are long and thin.
//
//   p, f, eta_c    at cell centres  ((i + 1/2) dx, (k + 1/2) dz),  i < nx, k < nz
//   u              at x-faces       (i dx, (k + 1/2) dz),          i < nx (face 0 = face nx)
//   w              at z-faces       ((i + 1/2) dx, k dz),          k <= nz (w = 0 at k = 0)
//   eta_n, tau_xz  at corners       (i dx, k dz),                  k <= nz
//
// All arrays are row-major in k (index k nx + i); periodicity is folded into wrap().
//
// The grid may move downslope at frame_speed U (the co-moving frame, twod/frame.hpp): the
// equations are Galilean invariant and the domain periodic, so only the bed changes, to a wall
// moving at -U. Velocities in the solver are then relative to the grid; twod/frame.hpp turns
// them and the positions back into the lab frame for every output.
#pragma once

#include <cstddef>

namespace granbench::twod {

struct Grid {
  int nx = 0, nz = 0;
  double Lx = 0.0, Lz = 0.0;
  double dx = 0.0, dz = 0.0;
  double frame_speed = 0.0;  // the grid's downslope speed relative to the bed [m/s]

  Grid() = default;
  Grid(int nx_, int nz_, double Lx_, double Lz_)
      : nx(nx_), nz(nz_), Lx(Lx_), Lz(Lz_), dx(Lx_ / nx_), dz(Lz_ / nz_) {}

  int wrap(int i) const { return i < 0 ? i + nx : (i >= nx ? i - nx : i); }
  // Cell (i, k), u-face (i, k), w-face (i, k) and corner (i, k) all index as k nx + i.
  std::size_t at(int i, int k) const { return std::size_t(k) * nx + wrap(i); }
  std::size_t cells() const { return std::size_t(nx) * nz; }
  std::size_t w_faces() const { return std::size_t(nx) * (nz + 1); }
  std::size_t corners() const { return std::size_t(nx) * (nz + 1); }
  double xc(int i) const { return (i + 0.5) * dx; }
  double zc(int k) const { return (k + 0.5) * dz; }
  double cell_volume() const { return dx * dz; }
  double bed_velocity() const { return -frame_speed; }  // the bed's u in the grid's frame
};

// The domain height, close to Lz_over_h0 h0, that puts a surface of height h0 in the middle of a
// cell of an nz-cell column: h0 = (n - 1/2) dz with n = round(nz / Lz_over_h0). The 2D growth rate
// depends on where the surface sits in its cell (surface on a face, 1/4, 1/2, 3/4 of a cell:
// 1.03, 1.06, 1.04, 1.02 1/s for the §7 case at 32 cells per h0 with the default surface-row
// force; 0.99, 0.99, 1.05, 1.11 with the standard MAC force); the default grids use mid-cell so
// that their results do not depend on h0/dz (docs/twod-validation.md §4).
inline double mid_cell_domain_height(double h0, int nz, double Lz_over_h0 = 2.0) {
  const double n = static_cast<double>(static_cast<long>(nz / Lz_over_h0 + 0.5));
  return nz * h0 / (n - 0.5);
}

}  // namespace granbench::twod

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
#pragma once

#include <cstddef>

namespace granbench::twod {

struct Grid {
  int nx = 0, nz = 0;
  double Lx = 0.0, Lz = 0.0;
  double dx = 0.0, dz = 0.0;

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
};

}  // namespace granbench::twod

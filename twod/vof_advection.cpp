// Geometric, mass-conserving volume-of-fluid advection of the granular fraction f
// (Weymouth & Yue 2010, J. Comput. Phys. 229; PLIC geometry in plic.cpp).
//
// The colour function obeys  df/dt + div(u f) - f div(u) = 0  with div(u) = 0. Split into one
// sweep per direction d (x then z, or z then x on alternate steps), each sweep is
//
//   f^{s+1}_i = f^s_i - (F_{i+1/2} - F_{i-1/2}) + c_i (s_{i+1/2} - s_{i-1/2}),
//
// where s = u_d dt / dx_d is the face Courant number, F the fluid volume (in cell units) that
// crosses the face: the part of the upwind cell's PLIC polygon lying within |s| of the face,
// and c_i = 1 if f^n_i > 1/2 else 0 is frozen at the start of the step. Because c is the same
// in both sweeps, the correction terms sum to c_i dt div(u)_i = 0: the total volume changes
// only by the boundary fluxes (none here: w = 0 at the bed, f = 0 at the top), i.e. it is
// conserved to round-off, and f stays in [0, 1] for |s| < 1/2.
//
// Normals: Youngs' 3x3 weighted gradient  m = -grad f  (cell-unit coordinates), with f
// periodic in x and mirrored (zero gradient) at the bed and the top.
// Threads: the fluxes of a sweep read f only and the update writes each cell once, so both
// loops are parallel over rows (parallel.hpp).
#include "twod/vof_advection.hpp"

#include <algorithm>
#include <cmath>

#include "twod/fill_fraction.hpp"
#include "twod/parallel.hpp"
#include "twod/plic.hpp"

namespace granbench::twod {

namespace {
double f_at(const Grid& g, const std::vector<double>& f, int i, int k) {
  k = std::clamp(k, 0, g.nz - 1);
  return f[g.at(i, k)];
}

// Volume (cell units) leaving the donor cell through its face on the `upper` side in direction
// `dir` (0: x, 1: z), for a Courant number magnitude s <= 1.
double donor_flux(const Grid& g, const std::vector<double>& f, int i, int k, int dir, bool upper,
                  double s) {
  const double fc = f[g.at(i, k)];
  if (!is_cut(fc)) return s * fc;
  double m1, m2;
  youngs_normal(g, f, i, k, m1, m2);
  if (m1 == 0.0 && m2 == 0.0) return s * fc;
  const double alpha = plic_alpha(m1, m2, fc);
  const double x0 = upper ? 1.0 - s : 0.0;
  const double frac = dir == 0 ? plic_rect_fraction(m1, m2, alpha, x0, s, 0.0, 1.0)
                               : plic_rect_fraction(m1, m2, alpha, 0.0, 1.0, x0, s);
  return s * frac;
}

void sweep(const Grid& g, const std::vector<double>& u, const std::vector<double>& w, double dt,
           int dir, const std::vector<char>& c, std::vector<double>& f, std::vector<double>& flux,
           std::vector<double>& clipped_rows, VofStats& stats) {
  const int nx = g.nx, nz = g.nz;
  if (dir == 0) {
    const double r = dt / g.dx;
    flux.resize(g.cells());  // flux through x-face (i, k); every face written below
    // (rows in contiguous blocks, sized by the team's balance: only the few rows at the surface
    // need PLIC, and one block holds them all; see update_viscosity for why not interleaved)
    parallel_for(nz, true, [&](int k) {
      for (int i = 0; i < nx; ++i) {
        const double s = u[g.at(i, k)] * r;
        if (s > 0.0)
          flux[g.at(i, k)] = donor_flux(g, f, g.wrap(i - 1), k, 0, true, s);
        else if (s < 0.0)
          flux[g.at(i, k)] = -donor_flux(g, f, i, k, 0, false, -s);
        else
          flux[g.at(i, k)] = 0.0;
      }
    });
    parallel_for(nz, true, [&](int k) {
      for (int i = 0; i < nx; ++i) {
        const std::size_t a = g.at(i, k), b = g.at(i + 1, k);
        f[a] += -(flux[b] - flux[a]) + c[a] * r * (u[b] - u[a]);
      }
    });
  } else {
    const double r = dt / g.dz;
    flux.resize(g.w_faces());  // flux through z-face (i, k); every face written below
    for (int i = 0; i < nx; ++i) flux[g.at(i, 0)] = 0.0;  // the bed
    parallel_for(nz + 1 - 1, true, [&](int k_from_1) {
      const int k = k_from_1 + 1;
      for (int i = 0; i < nx; ++i) {
        const double s = w[g.at(i, k)] * r;
        if (s > 0.0)
          flux[g.at(i, k)] = donor_flux(g, f, i, k - 1, 1, true, s);
        else if (s < 0.0 && k < nz)
          flux[g.at(i, k)] = -donor_flux(g, f, i, k, 1, false, -s);
        else  // no flow, or inflow through the top, which carries light fluid only (f = 0)
          flux[g.at(i, k)] = 0.0;
      }
    });
    parallel_for(nz, true, [&](int k) {
      for (int i = 0; i < nx; ++i) {
        const std::size_t a = g.at(i, k), b = g.at(i, k + 1);
        f[a] += -(flux[b] - flux[a]) + c[a] * r * (w[b] - w[a]);
      }
    });
  }
  // Clip to [0, 1]; the clipped volume is summed per row, then over the rows in order, so that
  // it does not depend on the thread count.
  clipped_rows.assign(nz, 0.0);
  parallel_for(nz, true, [&](int k) {
    for (int i = 0; i < nx; ++i) {
      double& v = f[g.at(i, k)];
      if (v < 0.0) {
        clipped_rows[k] += -v;
        v = 0.0;
      } else if (v > 1.0) {
        clipped_rows[k] += v - 1.0;
        v = 1.0;
      }
    }
  });
  for (double row : clipped_rows) stats.clipped_volume += row;
}
}  // namespace

void youngs_normal(const Grid& g, const std::vector<double>& f, int i, int k, double& m1,
                   double& m2) {
  auto F = [&](int di, int dk) { return f_at(g, f, i + di, k + dk); };
  // -grad f in cell units: the dx, dz of the physical gradient cancel against the mapping.
  m1 = -((F(1, 1) + 2.0 * F(1, 0) + F(1, -1)) - (F(-1, 1) + 2.0 * F(-1, 0) + F(-1, -1))) / 8.0;
  m2 = -((F(1, 1) + 2.0 * F(0, 1) + F(-1, 1)) - (F(1, -1) + 2.0 * F(0, -1) + F(-1, -1))) / 8.0;
}

double largest_face_courant(const Grid& g, const std::vector<double>& u,
                            const std::vector<double>& w, double dt) {
  // u holds the g.cells() x-faces and w the g.w_faces() z-faces, so the maxima run over the
  // whole arrays (in parallel; a maximum is exact in any order)
  return std::max(parallel_max_abs(u) * dt / g.dx, parallel_max_abs(w) * dt / g.dz);
}

namespace {
// One split step (both sweeps) of length dt; the fluxes of each direction go to flux_x and
// flux_z when given.
void split_step(const Grid& g, const std::vector<double>& u, const std::vector<double>& w,
                double dt, bool x_first, std::vector<double>& f, VofStats& stats,
                VofWorkspace& work, std::vector<double>* flux_x, std::vector<double>* flux_z) {
  std::vector<char>& c = work.c;
  c.resize(f.size());
  parallel_for_ranges(int(f.size()), [&](int begin, int end) {
    for (int n = begin; n < end; ++n) c[n] = f[n] > 0.5 ? 1 : 0;  // Weymouth-Yue c_i
  });
  std::vector<double>& flux = work.flux;
  const int first = x_first ? 0 : 1;
  for (const int dir : {first, 1 - first}) {
    sweep(g, u, w, dt, dir, c, f, flux, work.clipped_rows, stats);
    std::vector<double>* out = dir == 0 ? flux_x : flux_z;
    if (out) out->swap(flux);  // (flux is rewritten in full)
  }
}
}  // namespace

void advect_volume_fraction(const Grid& g, const std::vector<double>& u,
                            const std::vector<double>& w, double dt, bool x_first,
                            std::vector<double>& f, VofStats& stats, VofWorkspace& work,
                            GrainFluxes* fluxes) {
  // The step's dt bounds the Courant number of u^n (time_step.cpp), not of the velocity the
  // interface moves with (the mid-step extrapolation, solver.cpp), which a violent event (a
  // splash, a front breaking) can take past 1/2, where the sweeps no longer keep f in [0, 1]
  // and clipping loses grains. Such a step is advanced in equal sub-steps of Courant number at
  // most kSubstepCourant, with the same velocity; each conserves the volume, and the fluxes
  // add up over them. Every other step is one split step, as before.
  const double courant = largest_face_courant(g, u, w, dt);
  const int substeps = courant <= 0.5 ? 1 : int(std::ceil(courant / kSubstepCourant));
  if (substeps == 1) {
    split_step(g, u, w, dt, x_first, f, stats, work, fluxes ? &fluxes->x : nullptr,
               fluxes ? &fluxes->z : nullptr);
    return;
  }
  ++stats.substepped_steps;
  if (fluxes) {
    fluxes->x.assign(g.cells(), 0.0);
    fluxes->z.assign(g.w_faces(), 0.0);
  }
  const double h = dt / substeps;
  for (int m = 0; m < substeps; ++m) {
    split_step(g, u, w, h, (m % 2 == 0) == x_first, f, stats, work, fluxes ? &work.flux_x : nullptr,
               fluxes ? &work.flux_z : nullptr);
    if (!fluxes) continue;
    for (std::size_t n = 0; n < fluxes->x.size(); ++n) fluxes->x[n] += work.flux_x[n];
    for (std::size_t n = 0; n < fluxes->z.size(); ++n) fluxes->z[n] += work.flux_z[n];
  }
}

}  // namespace granbench::twod

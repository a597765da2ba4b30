// Advection of the granular volume fraction f by the face velocities (vof_advection.cpp).
#pragma once

#include <vector>

#include "twod/grid.hpp"

namespace granbench::twod {

struct VofStats {
  double clipped_volume = 0.0;  // |volume| removed by clipping f to [0, 1] (should stay ~1e-16)
  long substepped_steps = 0;    // steps advanced in sub-steps (advect_volume_fraction)
};

// The largest face Courant number for which one split step is taken; a step above 1/2 is split
// into sub-steps of at most this.
inline constexpr double kSubstepCourant = 0.45;

// Grain volume that crossed each face in one step, in cell units (of dx dz): x at x-face (i, k),
// z at z-face (i, k) (nz + 1 rows).
struct GrainFluxes {
  std::vector<double> x, z;
};

// The step's scratch arrays, kept by the caller from step to step so that a step allocates
// nothing (see PcgWorkspace for why).
struct VofWorkspace {
  std::vector<char> c;  // the Weymouth-Yue indicator of the step's start
  std::vector<double> flux, clipped_rows;
  std::vector<double> flux_x, flux_z;  // one sub-step's fluxes (sub-stepped steps only)
};

// One time step of directionally split PLIC advection with the Weymouth-Yue correction;
// `x_first` alternates the sweep order from step to step. u, w are the (discretely
// divergence-free) face velocities of the step. When `fluxes` is given, it receives the step's
// face fluxes (for momentum carried consistently with f). A step whose largest face Courant
// number exceeds 1/2 is taken in equal sub-steps (stats.substepped_steps counts them), so that
// f stays in [0, 1] without clipping.
void advect_volume_fraction(const Grid& g, const std::vector<double>& u,
                            const std::vector<double>& w, double dt, bool x_first,
                            std::vector<double>& f, VofStats& stats, VofWorkspace& work,
                            GrainFluxes* fluxes = nullptr);

// max(|u| dt/dx, |w| dt/dz) over the faces.
double largest_face_courant(const Grid& g, const std::vector<double>& u,
                            const std::vector<double>& w, double dt);

// Youngs normal (pointing out of the fluid) of cell (i, k) in cell-unit coordinates.
void youngs_normal(const Grid& g, const std::vector<double>& f, int i, int k, double& m1,
                   double& m2);

}  // namespace granbench::twod

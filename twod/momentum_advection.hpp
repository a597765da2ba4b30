// Explicit momentum advection (u . grad) u on the MAC grid (momentum_advection.cpp), carried by
// the velocity (the default) or by the mass fluxes of the VOF step (consistent transport).
#pragma once

#include <vector>

#include "twod/fields.hpp"
#include "twod/grid.hpp"
#include "twod/vof_advection.hpp"

namespace granbench::twod {

// The faces of the staggered control volumes, each computed once and read by the two volumes
// that share it: the carrier C (the average of two carriers) and the flux C q with q upwinded.
// Scratch kept by the caller from one step to the next (no allocation per step).
struct AdvectionFaces {
  std::vector<double> ux_c, ux_f;  // u-volumes' x-faces, at cell centres (i, k)
  std::vector<double> uz_c, uz_f;  // u-volumes' z-faces, at corners (i, k), k = 0 .. nz
  std::vector<double> wx_c, wx_f;  // w-volumes' x-faces, at corners (i, k), k = 1 .. nz - 1 used
  std::vector<double> wz_c, wz_f;  // w-volumes' z-faces, at cell centres (i, k)
  std::vector<double> ux_p, uz_p, wx_p, wz_p;  // the same faces' fluxes of a carried field
};

// A field laid out like u and w that the advection carries along with the momentum, by the same
// carriers, upwind sides and time centring (the BDF2 step's memory, solver.cpp): its transport
// term goes to adv_u, adv_w, so that (u - dt adv_u, w - dt adv_w) is the field moved over the
// step with the material. u == nullptr: none.
struct CarriedField {
  const std::vector<double>* u = nullptr;
  const std::vector<double>* w = nullptr;
  std::vector<double>* adv_u = nullptr;
  std::vector<double>* adv_w = nullptr;
};

// adv_u at every u-face, adv_w at the interior w-faces (k = 1 .. nz-1; others left 0).
void momentum_advection(const Grid& g, const Fields& s, AdvectionFaces& faces,
                        std::vector<double>& adv_u, std::vector<double>& adv_w,
                        const CarriedField& carried = {});

// Mass fluxes through the cell faces over one step [kg m^-2 s^-1]: x at x-face (i, k), z at
// z-face (i, k) (nz + 1 rows).
struct MassFluxes {
  std::vector<double> x, z;
};

// The mass that the VOF step moved through each face: its grain volume at rho_g and the rest of
// the face's volume flux u dt at rho_l, per unit area and time.
void mass_fluxes(const Grid& g, const Fields& s, const GrainFluxes& grains, double rho_g,
                 double rho_l, double dt, MassFluxes& m);

// The same operator with the mass fluxes m as carriers, its face values centred in time (along
// the face's normal and, with transverse_terms, across it), normalised by the density that these
// fluxes leave in each control volume, rho^n - dt div(m) (rho_u, rho_w: the face densities at
// level n). In a region of one density it equals momentum_advection's value to O(dt div u); across
// the interface it carries momentum with the mass that the VOF step moves, so a parcel of grains
// keeps its own velocity as it crosses faces that held light fluid (Rudman 1997).
void consistent_momentum_advection(const Grid& g, const Fields& s, const MassFluxes& m,
                                   const std::vector<double>& rho_u,
                                   const std::vector<double>& rho_w, double dt,
                                   AdvectionFaces& faces, std::vector<double>& adv_u,
                                   std::vector<double>& adv_w, const CarriedField& carried = {},
                                   bool transverse_terms = true);

}  // namespace granbench::twod

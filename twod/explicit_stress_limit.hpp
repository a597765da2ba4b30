// How much of the mu(I) stress the viscous step may leave explicit.
//
// With the stress linearised about u^n (SolverParams::viscosity_tangent) the matrix carries the
// tangent viscosity eta_t and S(eta - eta_t) u^n goes to the right-hand side (viscous_step.cpp).
// An explicit stress is stable only while it moves a face by less than the face's own mass
// allows: (eta - eta_m) dt / (rho h^2) <= 1 with h = min(dx, dz). The implicit part is therefore
//
//   eta_m = max(eta_t, eta - rho h^2 / dt),
//
// rho the density of the lightest face the stress point acts on (a cell's four faces, a
// corner's two u-faces and two w-faces). Inside the grains this is the tangent (in the §7 flow
// (eta - eta_t) dt / (rho h^2) < 0.4). At a point next to a face that holds mostly light fluid
// (under an overturned front, beside a pocket of light fluid) it is the whole secant: taking the
// grains' density there, as the limit did before, left an explicit stress up to 10^5 times what
// the light face's mass can carry; the 12 cm eigenmode rollwave ran away in such a pocket at
// 8.08 s (docs/twod-validation.md §11 item 9).
#pragma once

#include <vector>

#include "twod/fields.hpp"
#include "twod/grid.hpp"

namespace granbench::twod {

// The density of the lightest of the four faces around cell (i, k), and around corner (i, k)
// (corners on the bed and the top have one u-face).
double lightest_face_density_around_cell(const Grid& g, const Properties& props, int i, int k);
double lightest_face_density_around_corner(const Grid& g, const Properties& props, int i, int k);

// eta_m at the cells and corners for a step of dt, from props' eta, eta_t and face densities.
void implicit_viscosities(const Grid& g, const Properties& props, double dt,
                          std::vector<double>& implicit_c, std::vector<double>& implicit_n);

}  // namespace granbench::twod

// Initial states of the 2D solver (initial_state.cpp). An initial condition is a surface
// h(x) and a downslope velocity u(x, z); the vertical velocity follows from the discrete
// continuity equation (kinematically consistent) and the pressure is the discrete hydrostatic
// pressure of the layer, so other initial conditions (e.g. a linear eigenmode) only supply
// these two functions.
#pragma once

#include <functional>

#include "common/steady_state.hpp"
#include "twod/fields.hpp"
#include "twod/grid.hpp"
#include "twod/parameters.hpp"

namespace granbench::twod {

struct InitialCondition {
  std::function<double(double x)> height;              // h(x) [m]
  std::function<double(double x, double z)> velocity;  // u(x, z) [m/s], z in [0, Lz]
};

// (7.2): h = h0 + a0 sin(2 pi x / Lx), with the Bagnold velocity (5.5) of the local depth h(x)
// below the surface and its surface value above it.
InitialCondition perturbed_bagnold(const SteadyState& steady, double a0, double Lx);
// A flat layer of depth h0 at rest.
InitialCondition layer_at_rest(double h0);

// f (cell-averaged), u at the faces, w from continuity, p hydrostatic (5.4) on the discrete
// grid with p = 0 at the top.
Fields make_initial_state(const Grid& g, const InitialCondition& ic, const SolverParams& params);

// The discrete hydrostatic pressure of the densities in props: exact balance with gravity on
// every z-face, p = 0 at z = Lz.                                                        (5.4)
void hydrostatic_pressure(const Grid& g, const Properties& props, double g_cos_zeta,
                          std::vector<double>& p);

}  // namespace granbench::twod

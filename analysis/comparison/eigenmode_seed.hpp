// Seeding the 2D solver with the exact linear eigenmode: the twod initial
// condition (surface h(x) and downslope velocity u(x, z); the solver derives w from continuity
// and p hydrostatically, twod/initial_state.hpp) built from linear2d::Eigenmode
// (analysis/linear2d/eigenmode.hpp):
//
//   h(x) = h0 + a cos(k x),   u(x, z) = U0(z) + Re(a u_hat(z) e^{ikx})   for z <= h(x),
//
// with the value at the surface continued above it. Lives in the comparison layer because it
// joins the twod and analysis libraries, which do not depend on each other.
#pragma once

#include "analysis/linear2d/eigenmode.hpp"
#include "twod/initial_state.hpp"

namespace granbench {

twod::InitialCondition eigenmode_initial_condition(const linear2d::Eigenmode& mode, double a);

}  // namespace granbench

// The eigenmode initial condition of the 2D solver; see eigenmode_seed.hpp.
#include "analysis/comparison/eigenmode_seed.hpp"

#include <algorithm>

namespace granbench {

twod::InitialCondition eigenmode_initial_condition(const linear2d::Eigenmode& mode, double a) {
  twod::InitialCondition ic;
  ic.height = [mode, a](double x) { return mode.height(x, a); };
  ic.velocity = [mode, a](double x, double z) {
    const double zc = std::min(z, mode.height(x, a));  // surface value above the layer
    return mode.seeded_state(x, zc, a).u;
  };
  return ic;
}

}  // namespace granbench

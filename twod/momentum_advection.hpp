// Explicit momentum advection (u . grad) u on the MAC grid (momentum_advection.cpp).
#pragma once

#include <vector>

#include "twod/fields.hpp"
#include "twod/grid.hpp"

namespace granbench::twod {

// adv_u at every u-face, adv_w at the interior w-faces (k = 1 .. nz-1; others left 0).
void momentum_advection(const Grid& g, const Fields& s, std::vector<double>& adv_u,
                        std::vector<double>& adv_w);

}  // namespace granbench::twod

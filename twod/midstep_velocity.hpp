// The velocity that moves the interface over a step (SolverParams::interface_midstep_velocity)
// and the limit on its extrapolated part (midstep_velocity.cpp).
#pragma once

#include "twod/fields.hpp"
#include "twod/grid.hpp"

namespace granbench::twod {

// u^{n+1/2} = u^n + e,  e = (r/2)(u^n - u^{n-1}),  r = dt / dt_{n-1},
// with e clipped on each face to the speed that moves the face's fluid `limit_cells` of a cell
// over the step dt: |e| <= limit_cells dx / dt on u-faces, limit_cells dz / dt on w-faces.
// `midstep` receives u and w (its other fields are left alone). Returns the number of faces
// whose e was clipped. Every face is computed by the same arithmetic for any thread count.
long midstep_velocity(const Grid& g, const Fields& now, const Fields& previous, double r, double dt,
                      double limit_cells, Fields& midstep);

}  // namespace granbench::twod

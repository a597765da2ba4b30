// CFL-limited adaptive time step with smoothed growth:
//
//   dt = min( cfl min(dx / max|u|, dz / max|w|),  dt_growth dt_prev,  dt_max ).
//
// Advection (momentum and the split VOF, which needs |u| dt/dx < 1/2 per direction) is the
// only explicit part; viscosity is implicit and imposes no limit. The growth cap keeps dt from
// jumping when the flow starts from rest.
#include "twod/time_step.hpp"

#include <algorithm>
#include <cmath>

#include "twod/parallel.hpp"

namespace granbench::twod {

double choose_time_step(const Grid& g, const Fields& s, const SolverParams& params,
                        double dt_previous) {
  // (parallel; a max is exact in any order, so it does not depend on the thread count)
  const double umax = parallel_max_abs(s.u), wmax = parallel_max_abs(s.w);
  double dt = params.dt_max;
  if (umax > 0.0) dt = std::min(dt, params.cfl * g.dx / umax);
  if (wmax > 0.0) dt = std::min(dt, params.cfl * g.dz / wmax);
  if (dt_previous > 0.0) dt = std::min(dt, params.dt_growth * dt_previous);
  return dt;
}

}  // namespace granbench::twod

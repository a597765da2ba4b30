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

namespace granbench::twod {

double choose_time_step(const Grid& g, const Fields& s, const SolverParams& params,
                        double dt_previous) {
  // (a max is exact in any order, so the reduction does not depend on the thread count)
  double umax = 0.0, wmax = 0.0;
  const long nu = long(s.u.size()), nw = long(s.w.size());
#pragma omp parallel for schedule(static) reduction(max : umax)
  for (long n = 0; n < nu; ++n) umax = std::max(umax, std::abs(s.u[n]));
#pragma omp parallel for schedule(static) reduction(max : wmax)
  for (long n = 0; n < nw; ++n) wmax = std::max(wmax, std::abs(s.w[n]));
  double dt = params.dt_max;
  if (umax > 0.0) dt = std::min(dt, params.cfl * g.dx / umax);
  if (wmax > 0.0) dt = std::min(dt, params.cfl * g.dz / wmax);
  if (dt_previous > 0.0) dt = std::min(dt, params.dt_growth * dt_previous);
  return dt;
}

}  // namespace granbench::twod

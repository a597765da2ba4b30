// The interface's mid-step velocity, and why its extrapolation is limited.
//
// The VOF step moves the surface over [t^n, t^{n+1}] with u^{n+1/2} = u^n + (r/2)(u^n - u^{n-1}),
// which removes the first-order lag of the kinematic condition (docs/twod-validation.md §2): where
// u is smooth in time the extrapolated part e = (r/2)(u^n - u^{n-1}) is O(dt du/dt), and the
// displacement it adds over the step, e dt, is the O(dt^2) term of the face's trajectory.
//
// Where u is not resolved in time it is not. Under a front that overturns, a pocket of the light
// fluid (10^5 times lighter than the grains) is squeezed out as the grains close over it, and its
// faces change speed by metres per second from one step to the next. In the paper's 12 cm sine
// rollwave at 48 cells per h0 (360 x 96) such an event ran away at 3.59 s: just after a step
// shortened to land on an output time, the light fluid's speed next to a one-cell column of
// grains roughly doubled at every step while the CFL halved the step, from 3 m/s to 10^4 m/s
// within a millisecond, with a pressure dipole across the column growing alike. The gain is per
// step, whatever dt. Restarted from a checkpoint 25 steps before, the run diverged the same way
// with each of six other parts of the step turned off alone, and completed with the extrapolation
// off (or BDF2 off); with e clipped to move a face at most 0.05 or 0.1 of a cell it completed, at
// 0.2 or more it diverged as before (the largest e dt before the run-away was 0.26 of a cell). Our
// reading: an extrapolated jump moves the grains on the pocket's rim too far, the projection
// answers the misplaced mass with a pressure kick, and the kick is the next step's jump
// (docs/twod-validation.md §11, item 9).
//
// So e is clipped on each face to move the fluid at most `limit_cells` of a cell over the step
// (SolverParams::midstep_extrapolation_limit, 0.05: an eighth of the CFL's 0.4). Where the flow is
// resolved in time the clip does not act (no face in the main job's run) and the step is bitwise
// the same; where it acts, the interface moves with u^n plus a bounded part of the jump: first
// order in time for that face and that step, as with any limiter.
#include "twod/midstep_velocity.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "twod/parallel.hpp"

namespace granbench::twod {

long midstep_velocity(const Grid& g, const Fields& now, const Fields& previous, double r, double dt,
                      double limit_cells, Fields& midstep) {
  const double c = 0.5 * r;
  const double bound_u = limit_cells * g.dx / dt, bound_w = limit_cells * g.dz / dt;
  midstep.u.resize(now.u.size());
  midstep.w.resize(now.w.size());
  // Clipped faces counted per row and summed in row order: the same count for any thread count.
  std::vector<long> clipped(std::size_t(2 * g.nz + 1), 0);
  auto extrapolate = [c](double a, double b, double bound, long& count) {
    const double e = c * (a - b);
    if (std::abs(e) <= bound) return a + e;
    ++count;
    return a + std::copysign(bound, e);
  };
  parallel_for(g.nz, true, [&](int k) {  // u-faces, row k
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t f = g.at(i, k);
      midstep.u[f] = extrapolate(now.u[f], previous.u[f], bound_u, clipped[std::size_t(k)]);
    }
  });
  parallel_for(g.nz + 1, true, [&](int k) {  // w-faces, row k (the bed's and the lid's too)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t f = g.at(i, k);
      midstep.w[f] = extrapolate(now.w[f], previous.w[f], bound_w, clipped[std::size_t(g.nz + k)]);
    }
  });
  long total = 0;
  for (long n : clipped) total += n;
  return total;
}

}  // namespace granbench::twod

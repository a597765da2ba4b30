// The interface's mid-step velocity (twod/midstep_velocity.hpp): where u changes smoothly from
// step to step it is the extrapolation u^n + (r/2)(u^n - u^{n-1}) to the last bit; a face whose
// velocity jumps has its extrapolated part clipped to move the face's fluid the limit's fraction
// of a cell over the step, with the jump's sign, and is counted; u-faces are bounded by dx, w-faces
// by dz.
#include <gtest/gtest.h>

#include <cmath>

#include "twod/midstep_velocity.hpp"

using namespace granbench::twod;

namespace {

struct Levels {
  Grid grid{8, 6, 0.008, 0.003};  // dx = 1 mm, dz = 0.5 mm
  Fields now, previous;
  Levels() {
    now.u.resize(grid.cells());
    now.w.resize(grid.w_faces());
    previous = now;
    // a smooth flow changing by about 1e-3 m/s per step
    for (std::size_t n = 0; n < now.u.size(); ++n) {
      previous.u[n] = 1.0 + 0.01 * std::sin(0.7 * double(n));
      now.u[n] = previous.u[n] + 1e-3 * std::cos(0.3 * double(n));
    }
    for (std::size_t n = 0; n < now.w.size(); ++n) {
      previous.w[n] = 0.02 * std::cos(0.5 * double(n));
      now.w[n] = previous.w[n] - 5e-4 * std::sin(0.9 * double(n));
    }
  }
};

constexpr double kDt = 1e-4, kR = 0.8, kLimit = 0.01;

}  // namespace

TEST(MidstepVelocity, ResolvedChangeIsTheExtrapolationBitwise) {
  Levels l;
  Fields mid;
  const long clipped = midstep_velocity(l.grid, l.now, l.previous, kR, kDt, kLimit, mid);
  EXPECT_EQ(clipped, 0);
  for (std::size_t n = 0; n < l.now.u.size(); ++n)
    EXPECT_EQ(mid.u[n], l.now.u[n] + 0.5 * kR * (l.now.u[n] - l.previous.u[n]));
  for (std::size_t n = 0; n < l.now.w.size(); ++n)
    EXPECT_EQ(mid.w[n], l.now.w[n] + 0.5 * kR * (l.now.w[n] - l.previous.w[n]));
}

TEST(MidstepVelocity, AJumpIsClippedToTheLimitsDisplacement) {
  Levels l;
  // a u-face whose light fluid sped up by 5 m/s in one step, a w-face slowed by 3 m/s
  const std::size_t fu = l.grid.at(3, 4), fw = l.grid.at(5, 2);
  l.now.u[fu] = l.previous.u[fu] + 5.0;
  l.now.w[fw] = l.previous.w[fw] - 3.0;
  Fields mid;
  const long clipped = midstep_velocity(l.grid, l.now, l.previous, kR, kDt, kLimit, mid);
  EXPECT_EQ(clipped, 2);
  // (r/2) 5 m/s = 2 m/s would move the face 0.2 mm = 0.2 dx over the step: clipped to 0.01 dx
  EXPECT_DOUBLE_EQ(mid.u[fu], l.now.u[fu] + kLimit * l.grid.dx / kDt);
  EXPECT_DOUBLE_EQ(mid.w[fw], l.now.w[fw] - kLimit * l.grid.dz / kDt);
  EXPECT_NEAR((mid.u[fu] - l.now.u[fu]) * kDt, kLimit * l.grid.dx, 1e-15);
  // every other face keeps its extrapolation
  for (std::size_t n = 0; n < l.now.u.size(); ++n)
    if (n != fu) EXPECT_EQ(mid.u[n], l.now.u[n] + 0.5 * kR * (l.now.u[n] - l.previous.u[n]));
}

TEST(MidstepVelocity, InfiniteLimitKeepsEveryJump) {
  Levels l;
  const std::size_t fu = l.grid.at(0, 0);
  l.now.u[fu] = l.previous.u[fu] - 40.0;
  Fields mid;
  EXPECT_EQ(midstep_velocity(l.grid, l.now, l.previous, kR, kDt, INFINITY, mid), 0);
  EXPECT_EQ(mid.u[fu], l.now.u[fu] + 0.5 * kR * (l.now.u[fu] - l.previous.u[fu]));
}

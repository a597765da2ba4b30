// depthavg::Solver::run keeps its samples when anything in its time loop throws (a callback, a
// full disk, memory): status Failed, the time and the cause, instead of an exception that loses
// the whole run.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"
#include "depthavg/initial_state.hpp"
#include "depthavg/solver.hpp"

namespace granbench {

TEST(DepthAvgRunFailure, AnExceptionInTheLoopKeepsTheSamplesWithTimeAndCause) {
  const Material material;
  const MuCurve curve(CurveKind::Regularised, material, 4e-3);
  const SteadyState base = steady_state(curve, degrees_to_radians(28.5), 4e-3);
  depthavg::SpaceParams space;
  space.nx = 32;
  const depthavg::Solver solver(base, curve, space, {});
  const auto U0 = depthavg::initial_state(solver.rhs(), {});
  depthavg::RunCallbacks cb;
  cb.progress = [](double t, double) {
    if (t > 0.025) throw std::runtime_error("no space left on device");
  };
  depthavg::OutputParams out;
  out.t_end = 1.0;
  out.dt_out = 0.01;
  depthavg::RunResult r;
  ASSERT_NO_THROW(r = solver.run(U0, out, cb));
  EXPECT_EQ(r.status, depthavg::RunStatus::Failed);
  EXPECT_EQ(r.series.nt(), 4u);  // t = 0 .. 0.03, the last sampled before its callback threw
  EXPECT_EQ(r.message.rfind("failed at t = 0.03", 0), 0u) << r.message;
  EXPECT_NE(r.message.find("no space left on device"), std::string::npos) << r.message;
  EXPECT_NEAR(r.t_reached, 0.03, 1e-12);
}

}  // namespace granbench

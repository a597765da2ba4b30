// The ambient pressure gradient along the slope (Rheology::ambient_pressure_gradient,
// twod/viscous_step.cpp). Above a steady layer the light fluid obeys eta_l u'' = -F along the
// slope with u = u_s at the surface and u' = 0 at the open top, F the force per volume along x
// that nothing balances. With the ambient gradient F = 0: the light layer moves with the surface,
// unsheared. Without it F = rho_l g sin(zeta): the light layer is the stream
//   u(z) - u_s = (rho_l g sin zeta / eta_l) (H s - s^2 / 2),  s = z - h,  H = Lz - h,
// which the centred stencil with the top's mirror ghost holds exactly (u'' is uniform). Both are
// checked between two rows of the light layer after eight of its viscous times (H^2 rho_l/eta_l).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/steady_state.hpp"
#include "twod/grid.hpp"
#include "twod/initial_state.hpp"
#include "twod/solver.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {
struct LightLayer {
  double shear_difference;   // u(top row) - u(lowest empty row), mean over the columns [m/s]
  double stream_difference;  // the same for the gravity-driven stream [m/s]
};

LightLayer light_layer_after(bool ambient_gradient) {
  const double h0 = 0.004, Lx = 0.008;
  SolverParams params;
  params.zeta = degrees_to_radians(28.5);
  params.rheology.ambient_pressure_gradient = ambient_gradient;
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, h0);
  const SteadyState steady = steady_state(curve, params.zeta, h0);
  const Grid g(8, 24, Lx, 2.1 * h0);  // surface at 11.43 of 24 rows
  Solver solver(g, params, make_initial_state(g, perturbed_bagnold(steady, 0.0, Lx), params));
  const Rheology& r = params.rheology;
  const double H = g.Lz - h0;
  const double viscous_time = H * H * r.rho_light / r.eta_light;
  while (solver.state().t < 8.0 * viscous_time) solver.step(1.0);

  const int k_low = int(std::ceil(h0 / g.dz)), k_top = g.nz - 1;  // the lowest row above h0
  double du = 0.0;
  for (int i = 0; i < g.nx; ++i)
    du += solver.state().u[g.at(i, k_top)] - solver.state().u[g.at(i, k_low)];
  du /= g.nx;
  const double G = r.rho_light * r.material.g * std::sin(params.zeta) / r.eta_light;
  auto stream = [&](double z) {
    const double s = z - h0;
    return G * (H * s - 0.5 * s * s);
  };
  const LightLayer l{du, stream(g.zc(k_top)) - stream(g.zc(k_low))};
  std::printf("ambient gradient %s: t = %.3f s, light layer's shear %.3e m/s, the stream's %.3e\n",
              ambient_gradient ? "on" : "off", solver.state().t, l.shear_difference,
              l.stream_difference);
  return l;
}
}  // namespace

TEST(AmbientPressureGradient, TheLightLayerMovesWithTheSurface) {
  const LightLayer l = light_layer_after(true);
  ASSERT_GT(l.stream_difference, 0.04);  // what the stream would make of it (0.05 m/s)
  EXPECT_LT(std::abs(l.shear_difference), 1e-3 * l.stream_difference);
}

TEST(AmbientPressureGradient, WithoutItTheLightLayerIsTheGravityDrivenStream) {
  const LightLayer l = light_layer_after(false);
  EXPECT_NEAR(l.shear_difference, l.stream_difference, 0.01 * l.stream_difference);
}

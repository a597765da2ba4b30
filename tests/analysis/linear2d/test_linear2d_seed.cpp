// Seeding the 2D solver with the exact eigenmode: the twod initial state built from
// eigenmode_initial_condition (analysis/comparison/eigenmode_seed.hpp) has the eigenmode's surface,
// and the vertical velocity the solver derives from discrete continuity reproduces the eigenmode's
// w(z) to the grid's second-order accuracy (kinematic consistency of the seed).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/comparison/eigenmode_seed.hpp"
#include "analysis/linear2d/eigenmode.hpp"

using namespace granbench;

TEST(Linear2DSeed, TwoDInitialStateCarriesTheEigenmode) {
  const Material m;
  const MuCurve curve(CurveKind::Regularised, m, 4e-3);
  const SteadyState s = steady_state(curve, degrees_to_radians(28.5), 4e-3);
  const double Lx = 0.08, a = 1e-5;
  const linear2d::Eigenmode mode = linear2d::surface_eigenmode(s, curve, Lx);
  const twod::InitialCondition ic = eigenmode_initial_condition(mode, a);
  EXPECT_NEAR(ic.height(0.0), s.h0 + a, 1e-15);
  EXPECT_NEAR(ic.height(0.25 * Lx), s.h0, 1e-12);

  double err_coarse = 0.0, scale = 0.0;
  for (int refine : {1, 2}) {
    const twod::Grid g(64 * refine, 32 * refine, Lx, 2.0 * s.h0);
    twod::SolverParams params;
    params.zeta = s.zeta;
    const twod::Fields f = twod::make_initial_state(g, ic, params);
    double err = 0.0;
    for (int i = 0; i < g.nx; i += 4 * refine)
      for (int k = 1; k <= g.nz / 4; ++k) {  // z-faces up to h0/2, inside the layer
        const double x = g.xc(i), z = k * g.dz;
        const double w_exact = (std::polar(a, mode.k() * x) * mode.w_hat(z)).real();
        err = std::max(err, std::abs(f.w[g.at(i, k)] - w_exact));
        scale = std::max(scale, std::abs(w_exact));
      }
    std::printf("grid %d x %d: max |w - w_eigenmode| = %.3e (max |w| = %.3e)\n", g.nx, g.nz, err,
                scale);
    if (refine == 1) {
      EXPECT_LT(err, 2e-2 * scale);
      err_coarse = err;
    } else {
      EXPECT_LT(err, 0.35 * err_coarse);  // second order: / 4 when dx and dz halve
    }
  }
}

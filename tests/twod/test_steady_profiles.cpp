// Exact steady profiles on an incline, reached by time stepping from the exact profile sampled
// on the grid, with the error measured over three resolutions (observed order of convergence).
//
// (a) Newtonian film (Nusselt): a layer of viscosity eta_g under the light fluid. With the
//     light fluid's weight included, the shear stress is tau(z) = g sin(zeta) (rho_g (h - z) +
//     rho_l (Lz - h)) below the surface, so  u = [g sin zeta/eta_g] (rho_g (h z - z^2/2) +
//     rho_l (Lz - h) z).  The MAC scheme integrates the exact corner stress with the midpoint
//     rule, so the error is second order.
// (b) Bagnold layer (5.4)-(5.5) at 24 deg with the regularised curve. The light fluid adds an
//     overburden p_s = rho_l g cos(zeta) (Lz - h) and the matching shear stress, so mu = tan
//     zeta holds everywhere and the exact profile is (5.5) with h replaced by h + delta,
//     delta = rho_l (Lz - h)/rho_g. du/dz ~ (h + delta - z)^{1/2} is not smooth at the surface,
//     which limits the max-norm order to 3/2 (midpoint rule next to a square-root point); the
//     test asserts order > 1.4 there and > 1.8 in the mean (L1) norm.
#include <gtest/gtest.h>

#include <cmath>

#include "common/steady_state.hpp"
#include "tests/support/verification_table.hpp"
#include "twod/initial_state.hpp"
#include "twod/solver.hpp"

using namespace granbench;
using namespace granbench::twod;
namespace vt = granbench::testing;

namespace {
struct Errors {
  double max = 0.0, l1 = 0.0;
};

// Run to t_end from the exact profile and compare the granular u-faces with it.
Errors steady_error(int nz, const SolverParams& params, double h,
                    const std::function<double(double)>& exact, double t_end) {
  const double Lz = 2.0 * h;
  const Grid g(4, nz, 0.02, Lz);
  InitialCondition ic{[h](double) { return h; },
                      [&](double, double z) { return exact(std::min(z, h)); }};
  Solver solver(g, params, make_initial_state(g, ic, params));
  solver.advance_to(t_end);
  Errors e;
  const double us = exact(h);
  int n = 0;
  for (int k = 0; g.zc(k) < h; ++k, ++n) {
    const double err = std::abs(solver.state().u[g.at(0, k)] - exact(g.zc(k))) / us;
    e.max = std::max(e.max, err);
    e.l1 += err;
  }
  e.l1 /= n;
  return e;
}

void expect_order(const std::vector<int>& nz, const std::vector<Errors>& e, double min_order_max,
                  double min_order_l1, vt::VerificationTable& table) {
  table.bound("observed order of the max error > " + vt::fixed(min_order_max, 1) +
              ", of the L1 error > " + vt::fixed(min_order_l1, 1) + " between successive grids");
  for (std::size_t n = 0; n < e.size(); ++n) {
    if (n == 0) {
      table.row(
          {std::to_string(nz[n]), vt::sci(e[n].max), vt::dash(), vt::sci(e[n].l1), vt::dash()});
      continue;
    }
    const double p_max = std::log2(e[n - 1].max / e[n].max);
    const double p_l1 = std::log2(e[n - 1].l1 / e[n].l1);
    table.row({std::to_string(nz[n]), vt::sci(e[n].max), vt::fixed(p_max), vt::sci(e[n].l1),
               vt::fixed(p_l1)});
    EXPECT_GT(p_max, min_order_max);
    EXPECT_GT(p_l1, min_order_l1);
  }
}

const std::vector<std::string> profile_columns{"nz (Lz = 2h)", "max error / u_s", "order",
                                               "L1 error / u_s", "order"};
}  // namespace

TEST(SteadyProfiles, NewtonianFilmIsNusselt) {
  SolverParams params;
  params.zeta = degrees_to_radians(10.0);
  params.rheology.newtonian_eta = 0.5;
  params.dt_max = 2e-3;
  const double h = 0.004, Lz = 2 * h;
  const double rg = params.rheology.material.bulk_density(), rl = params.rheology.rho_light;
  const double gs = params.rheology.material.g * std::sin(params.zeta);
  auto exact = [=](double z) {
    return gs / 0.5 * (rg * (h * z - 0.5 * z * z) + rl * (Lz - h) * z);
  };
  const std::vector<int> nz{16, 32, 64};
  std::vector<Errors> e;
  for (int n : nz) e.push_back(steady_error(n, params, h, exact, 0.4));
  vt::VerificationTable table(
      "twod_steady_nusselt", "2D model: Newtonian film (Nusselt) under the light fluid",
      "Steady u-profile after 0.4 s from the exact profile, 10 deg, eta = 0.5 Pa s, h = 4 mm; "
      "errors on the granular u-faces relative to the surface speed.",
      profile_columns);
  table.bound("the max error on the finest grid < 1e-3");
  expect_order(nz, e, 1.8, 1.8, table);
  EXPECT_LT(e.back().max, 1e-3);
  table.write();
}

TEST(SteadyProfiles, BagnoldLayerRegularised) {
  SolverParams params;
  params.zeta = degrees_to_radians(24.0);
  params.dt_max = 2e-3;
  const double h = 0.004, Lz = 2 * h;
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, h);
  const SteadyState steady = steady_state(curve, params.zeta, h);
  ASSERT_TRUE(steady.well_posed);
  const double delta =
      params.rheology.rho_light * (Lz - h) / params.rheology.material.bulk_density();
  auto exact = [=](double z) { return steady.velocity_at_depth(z, h + delta); };  // (5.5)
  const std::vector<int> nz{16, 32, 64};
  std::vector<Errors> e;
  for (int n : nz) e.push_back(steady_error(n, params, h, exact, 2.0));
  vt::VerificationTable table(
      "twod_steady_bagnold", "2D model: Bagnold layer (5.5), regularised curve",
      "Steady u-profile after 2 s from the exact profile, 24 deg, h = 4 mm; du/dz ~ (h - z)^(1/2) "
      "at the surface limits the max-norm order to 3/2.",
      profile_columns);
  table.bound("the max error on the finest grid < 2e-3");
  expect_order(nz, e, 1.4, 1.8, table);
  EXPECT_LT(e.back().max, 2e-3);
  table.write();
}

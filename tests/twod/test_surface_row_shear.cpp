// The shear-stress force on the w-faces around the surface row (twod/surface_row_shear.cpp).
// The MAC stencil gives the w-face below a partly filled row (fraction f) the x-derivative of the
// corner shear stress over the whole dz, and the w-face above nothing (its corners are light
// fluid). With the correction the two faces carry that derivative over the spans the grains fill
// on either side of the row's centroid, where the projection puts the row's pressure: (1 + f)/2 dz
// below, f/2 dz above, (1/2 + f) dz together, the height from the row below's centre to the
// surface. Checked per column for a graph surface with a stress that varies along x; zero for a
// flat layer, for columns whose surface row is not a graph, and away from the surface row. In a
// flat Bagnold layer stepped with it the correction stays at the projection's tolerance (the
// steady state is untouched).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/steady_state.hpp"
#include "twod/grid.hpp"
#include "twod/initial_state.hpp"
#include "twod/solver.hpp"
#include "twod/surface_row_shear.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {
// f of a layer whose surface lies at row k + fk in every column
std::vector<double> layer(const Grid& g, int k, double fk) {
  std::vector<double> f(g.cells(), 0.0);
  for (int i = 0; i < g.nx; ++i) {
    for (int j = 0; j < k; ++j) f[g.at(i, j)] = 1.0;
    f[g.at(i, k)] = fk;
  }
  return f;
}
}  // namespace

TEST(SurfaceRowShear, TheTwoFacesCarryTheStressDerivativeOverTheGrainsSpans) {
  const Grid g(8, 8, 0.008, 0.008);  // dz = 1 mm
  const int k = 5;
  for (const double fk : {0.1, 0.5, 0.9}) {
    const auto f = layer(g, k, fk);
    Properties props(g);
    // a corner stress that varies along x (and, to show that only row k's corners count, with
    // height): tau(i, j) = eta_n gamma_n = (1 + 0.1 j) (2 + sin(2 pi x_i / Lx))
    for (int j = 0; j <= g.nz; ++j)
      for (int i = 0; i < g.nx; ++i) {
        props.eta_n[g.at(i, j)] = 1.0 + 0.1 * j;
        props.gamma_n[g.at(i, j)] = 2.0 + std::sin(2.0 * M_PI * i * g.dx / g.Lx);
      }
    auto tau = [&](int i, int j) { return props.eta_n[g.at(i, j)] * props.gamma_n[g.at(i, j)]; };
    std::vector<double> F;
    surface_row_shear_correction(g, f, props, F);
    ASSERT_EQ(F.size(), g.w_faces());
    for (int i = 0; i < g.nx; ++i) {
      const double dtau = tau(i + 1, k) - tau(i, k);
      ASSERT_NE(dtau, 0.0);
      const double stencil_below = g.dz * dtau;  // what the stencil gives face k
      EXPECT_NEAR(stencil_below + F[g.at(i, k)], 0.5 * (1.0 + fk) * g.dz * dtau, 1e-15);
      EXPECT_NEAR(F[g.at(i, k + 1)], 0.5 * fk * g.dz * dtau, 1e-15);
      EXPECT_NEAR(stencil_below + F[g.at(i, k)] + F[g.at(i, k + 1)], (0.5 + fk) * g.dz * dtau,
                  1e-15);
      for (int j = 0; j <= g.nz; ++j) {
        if (j != k && j != k + 1) {
          EXPECT_EQ(F[g.at(i, j)], 0.0) << "face " << i << ", " << j;
        }
      }
    }
  }
}

TEST(SurfaceRowShear, NothingWhereTheStressIsUniformOrTheSurfaceIsNoGraph) {
  const Grid g(8, 8, 0.008, 0.008);
  const int k = 4;
  auto f = layer(g, k, 0.4);
  Properties props(g);
  for (std::size_t n = 0; n < props.eta_n.size(); ++n) {
    props.eta_n[n] = 0.3;
    props.gamma_n[n] = 7.0;
  }
  std::vector<double> F;
  surface_row_shear_correction(g, f, props, F);
  for (double v : F) EXPECT_EQ(v, 0.0);  // a flat layer: the same stress in every column

  for (int i = 0; i < g.nx; ++i) props.gamma_n[g.at(i, k)] = 7.0 + i;  // now it varies
  f[g.at(2, k + 1)] = 0.2;  // column 2: grains above its surface row (an overhang's lump)
  f[g.at(5, k - 1)] = 0.7;  // column 5: a cell below the surface row not full
  surface_row_shear_correction(g, f, props, F);
  for (int i : {2, 5})
    for (int j = 0; j <= g.nz; ++j) EXPECT_EQ(F[g.at(i, j)], 0.0) << "column " << i;
  EXPECT_NE(F[g.at(3, k)], 0.0);  // the others are corrected
}

TEST(SurfaceRowShear, TheVofRoundOffAroundTheRowLeavesItOn) {
  // With the surface on a cell face the VOF leaves wisps of 1e-22 above the films and 1 - 1e-16
  // below them; the row is still a graph surface's row and keeps its correction.
  const Grid g(8, 8, 0.008, 0.008);
  const int k = 4;
  Properties props(g);
  for (int j = 0; j <= g.nz; ++j)
    for (int i = 0; i < g.nx; ++i) {
      props.eta_n[g.at(i, j)] = 0.5;
      props.gamma_n[g.at(i, j)] = 3.0 + std::cos(2.0 * M_PI * i * g.dx / g.Lx);
    }
  for (const double fk : {0.01, 0.5}) {
    const auto clean = layer(g, k, fk);
    auto touched = clean;
    for (int i = 0; i < g.nx; ++i) {
      touched[g.at(i, k - 1)] = 1.0 - 1e-16;
      touched[g.at(i, k + 1)] = 1e-22;
      touched[g.at(i, k + 2)] = 1e-30;
    }
    std::vector<double> expected, F;
    surface_row_shear_correction(g, clean, props, expected);
    surface_row_shear_correction(g, touched, props, F);
    ASSERT_NE(expected[g.at(1, k)], 0.0);
    for (std::size_t n = 0; n < F.size(); ++n) EXPECT_EQ(F[n], expected[n]) << "face " << n;
  }
}

TEST(SurfaceRowShear, AFlatLayerFeelsOnlyRoundOff) {
  const double h0 = 0.004, Lx = 0.008;
  SolverParams off;
  off.surface_row_shear = false;
  off.zeta = degrees_to_radians(28.5);
  const MuCurve curve(CurveKind::Regularised, off.rheology.material, h0);
  const SteadyState steady = steady_state(curve, off.zeta, h0);
  SolverParams on = off;
  on.surface_row_shear = true;
  const Grid g(8, 24, Lx, 2.1 * h0);  // surface at 11.43 of 24 rows: mid-cell
  const Fields start = make_initial_state(g, perturbed_bagnold(steady, 0.0, Lx), off);
  Solver a(g, off, start), b(g, on, start);
  std::vector<double> F;
  for (int n = 0; n < 40; ++n) {
    a.step(1.0);
    b.step(1.0);
    // every column alike: the stress differs between columns only as much as the projection's
    // iterative solution does (its zebra line solves treat even and odd columns in turn: to its
    // tolerance, not to the bit), and the correction with it
    const Properties& props = b.properties();
    double tau_max = 0.0;
    for (std::size_t c = 0; c < props.eta_n.size(); ++c)
      tau_max = std::max(tau_max, std::abs(props.eta_n[c] * props.gamma_n[c]));
    surface_row_shear_correction(g, b.state().f, props, F);
    for (double v : F) ASSERT_LE(std::abs(v), on.solver_tolerance * g.dz * tau_max) << "step " << n;
  }
  // so the two runs agree to the projection's tolerance
  auto max_difference = [](const std::vector<double>& x, const std::vector<double>& y) {
    double d = 0.0;
    for (std::size_t n = 0; n < x.size(); ++n) d = std::max(d, std::abs(x[n] - y[n]));
    return d;
  };
  auto max_abs = [](const std::vector<double>& x) {
    double m = 0.0;
    for (double v : x) m = std::max(m, std::abs(v));
    return m;
  };
  const double tol = off.solver_tolerance;
  EXPECT_LT(max_difference(a.state().p, b.state().p), tol * max_abs(a.state().p));
  EXPECT_LT(max_difference(a.state().u, b.state().u), tol * max_abs(a.state().u));
  EXPECT_LT(max_difference(a.state().w, b.state().w), tol * max_abs(a.state().u));
}

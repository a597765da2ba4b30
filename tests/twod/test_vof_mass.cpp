// (c) The Weymouth-Yue split PLIC advection conserves the granular volume to round-off:
// 1000 steps of a wavy layer carried by a translation plus a swirl whose face velocities come
// from a stream function (so the discrete divergence is zero to round-off), at Courant number
// 0.4 with alternating sweep order. Also: f stays in [0, 1], and after one period of pure
// translation the interface is back where it started; and (d) below, steps above Courant
// number 1/2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "twod/diagnostics.hpp"
#include "twod/grid.hpp"
#include "twod/initial_state.hpp"
#include "twod/vof_advection.hpp"

using namespace granbench::twod;

namespace {
Grid make_grid() {
  return Grid(64, 32, 0.08, 0.008);
}

std::vector<double> wavy_layer(const Grid& g) {
  SolverParams params;
  InitialCondition ic{[&](double x) { return 0.004 + 0.001 * std::sin(2 * M_PI * x / g.Lx); },
                      [](double, double) { return 0.0; }};
  return make_initial_state(g, ic, params).f;
}

// A translation plus a swirl, from a stream function psi(x, z) = A sin(2 pi x/Lx) sin^2(pi z/Lz):
// u = U0 + dpsi/dz, w = -dpsi/dx on the faces, so the discrete divergence is zero to round-off.
void swirl(const Grid& g, std::vector<double>& u, std::vector<double>& w) {
  const double A = 2e-4, U0 = 0.5;
  auto psi = [&](int i, int k) {
    return A * std::sin(2 * M_PI * i * g.dx / g.Lx) * std::pow(std::sin(M_PI * k * g.dz / g.Lz), 2);
  };
  u.assign(g.cells(), 0.0);
  w.assign(g.w_faces(), 0.0);
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) u[g.at(i, k)] = U0 + (psi(i, k + 1) - psi(i, k)) / g.dz;
  for (int k = 0; k <= g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) w[g.at(i, k)] = -(psi(i + 1, k) - psi(i, k)) / g.dx;
}

// The wavy layer, the swirl and the layer's volume.
struct SwirlingLayer {
  std::vector<double> f, u, w;
  double V0;
};
SwirlingLayer swirling_layer(const Grid& g) {
  SwirlingLayer c{wavy_layer(g), {}, {}, 0.0};
  c.V0 = granular_volume(g, c.f);
  swirl(g, c.u, c.w);
  return c;
}

// The granular volume kept to round-off, nothing clipped, f in [0, 1].
void expect_conserved_and_bounded(const Grid& g, const std::vector<double>& f, double V0,
                                  const VofStats& stats) {
  const double V = granular_volume(g, f);
  std::printf("VOF volume: relative change %.3e, clipped %.3e\n", (V - V0) / V0,
              stats.clipped_volume * g.cell_volume() / V0);
  EXPECT_LT(std::abs(V - V0) / V0, 1e-12);
  EXPECT_LT(stats.clipped_volume * g.cell_volume() / V0, 1e-12);
  for (double v : f) {
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
  }
}
}  // namespace

TEST(VofMass, ConservedToRoundOffOver1000Steps) {
  const Grid g = make_grid();
  auto [f, u, w, V0] = swirling_layer(g);
  double umax = 0, wmax = 0;
  for (double v : u) umax = std::max(umax, std::abs(v));
  for (double v : w) wmax = std::max(wmax, std::abs(v));
  const double dt = 0.4 * std::min(g.dx / umax, g.dz / wmax);
  VofStats stats;
  VofWorkspace work;
  for (int n = 0; n < 1000; ++n) advect_volume_fraction(g, u, w, dt, n % 2 == 0, f, stats, work);
  expect_conserved_and_bounded(g, f, V0, stats);
  // the interface moved: the surface is no longer the initial one
  const auto h = surface_heights(g, f), h0 = surface_heights(g, wavy_layer(g));
  double diff = 0;
  for (int i = 0; i < g.nx; ++i) diff = std::max(diff, std::abs(h[i] - h0[i]));
  EXPECT_GT(diff, 1e-4);
}

TEST(VofMass, TranslationReturnsAfterOnePeriod) {
  const Grid g = make_grid();
  auto f = wavy_layer(g);
  const auto f0 = f;
  const double U0 = 0.3;
  std::vector<double> u(g.cells(), U0), w(g.w_faces(), 0.0);
  const int steps = 200;  // Courant number Lx/(steps dx) = 0.32
  const double dt = g.Lx / U0 / steps;
  VofStats stats;
  VofWorkspace work;
  for (int n = 0; n < steps; ++n) advect_volume_fraction(g, u, w, dt, n % 2 == 0, f, stats, work);
  double l1 = 0;
  for (std::size_t n = 0; n < f.size(); ++n) l1 += std::abs(f[n] - f0[n]) * g.cell_volume();
  // The shape error of PLIC translation is a fraction of the interface length times dx.
  EXPECT_LT(l1 / (g.Lx * g.dz), 0.05);
  EXPECT_NEAR(granular_volume(g, f), granular_volume(g, f0), 1e-12 * granular_volume(g, f0));
}

// (d) A step whose face Courant number exceeds 1/2 (the mid-step velocity of a violent event can
// take it there; vof_advection.cpp) is taken in sub-steps: the same swirl at Courant number 0.9
// for 500 steps keeps the volume to round-off, f in [0, 1] without clipping, and the returned
// fluxes are the step's: for a pure translation, each cell's change is minus the difference of
// its two x-face fluxes.
TEST(VofMass, StepsAboveCourantOneHalfAreSubsteppedAndConserve) {
  const Grid g = make_grid();
  auto [f, u, w, V0] = swirling_layer(g);
  const double dt = 0.9 / largest_face_courant(g, u, w, 1.0);
  EXPECT_NEAR(largest_face_courant(g, u, w, dt), 0.9, 1e-12);
  VofStats stats;
  VofWorkspace work;
  for (int n = 0; n < 500; ++n) advect_volume_fraction(g, u, w, dt, n % 2 == 0, f, stats, work);
  EXPECT_EQ(stats.substepped_steps, 500);
  expect_conserved_and_bounded(g, f, V0, stats);

  std::vector<double> ut(g.cells(), 0.3), wt(g.w_faces(), 0.0);
  const double dtt = 0.8 * g.dx / 0.3;  // Courant number 0.8: two sub-steps
  GrainFluxes fluxes;
  const auto before = f;
  advect_volume_fraction(g, ut, wt, dtt, true, f, stats, work, &fluxes);
  EXPECT_EQ(stats.substepped_steps, 501);
  double largest = 0.0;
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const double change = f[g.at(i, k)] - before[g.at(i, k)];
      const double out = fluxes.x[g.at(i + 1, k)] - fluxes.x[g.at(i, k)];
      largest = std::max(largest, std::abs(change + out));
    }
  EXPECT_LT(largest, 1e-14);
}

// The surface row's horizontal pressure force (twod/surface_row_pressure.cpp). A layer whose
// surface rises across the domain, h(x) = h0 + s x, through a cell face, under the pressure that
// the projection's hydrostatic balance produces (p = 0 at the top, p_{k-1} = p_k + g cos(zeta)
// rho_w(k) dz with rho_w from the face average of f, as in properties.cpp). On every partly
// filled u-face the standard force plus the correction must equal the hydrostatic force on the
// grains the face holds, -f_face dz (rho_g - rho_l) g cos(zeta) (h_i - h_{i-1}). Without a light
// fluid the standard force alone is 1/(2 f_face) times that where both cells share the surface row.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "twod/grid.hpp"
#include "twod/surface_row_pressure.hpp"

using namespace granbench::twod;

namespace {
void check(double rho_light) {
  const Grid g(16, 8, 0.016, 0.008);  // dz = 1 mm
  SolverParams params;
  params.zeta = 0.5;
  params.rheology.rho_light = rho_light;
  const double rho_g = params.rheology.material.bulk_density();
  const double g_cos = params.rheology.material.g * std::cos(params.zeta);
  auto rho = [&](double fr) { return fr * rho_g + (1.0 - fr) * rho_light; };
  const double h0 = 4.1e-3, slope = 0.04;  // h from 3.78 to 4.42 mm: crosses the face at 4 mm
  std::vector<double> f(g.cells(), 0.0), h(g.nx);
  for (int i = 0; i < g.nx; ++i) {
    h[i] = h0 + slope * (g.xc(i) - 0.5 * g.Lx);
    for (int k = 0; k < g.nz; ++k) f[g.at(i, k)] = std::clamp((h[i] - k * g.dz) / g.dz, 0.0, 1.0);
  }
  std::vector<double> p(g.cells(), 0.0);
  for (int i = 0; i < g.nx; ++i) {
    double pk = g_cos * rho(f[g.at(i, g.nz - 1)]) * 0.5 * g.dz;
    p[g.at(i, g.nz - 1)] = pk;
    for (int k = g.nz - 1; k > 0; --k) {
      pk += g_cos * rho(0.5 * (f[g.at(i, k - 1)] + f[g.at(i, k)])) * g.dz;
      p[g.at(i, k - 1)] = pk;
    }
  }
  const std::vector<double> correction = surface_row_pressure_correction(g, params, f, h);
  int partly_filled = 0, same_row = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int i = 1; i < g.nx; ++i) {  // i = 0 faces the jump of h across the periodic boundary
      const double f_face = 0.5 * (f[g.at(i - 1, k)] + f[g.at(i, k)]);
      const double standard = -g.dz * (p[g.at(i, k)] - p[g.at(i - 1, k)]);
      const double scale = g.dz * rho_g * g_cos * slope * g.dx;
      if (f_face > 0.0 && f_face < 1.0) {
        ++partly_filled;
        const double exact = -f_face * g.dz * (rho_g - rho_light) * g_cos * (h[i] - h[i - 1]);
        EXPECT_NEAR(standard + correction[g.at(i, k)], exact, 1e-12 * scale) << i << ", " << k;
        const bool shared = f[g.at(i - 1, k)] > 0.0 && f[g.at(i - 1, k)] < 1.0 &&
                            f[g.at(i, k)] > 0.0 && f[g.at(i, k)] < 1.0;
        if (shared && rho_light == 0.0) {
          ++same_row;
          EXPECT_NEAR(standard, exact / (2.0 * f_face), 1e-9 * scale);
        }
      } else {
        EXPECT_NEAR(standard,
                    f_face == 1.0 ? -g.dz * (rho_g - rho_light) * g_cos * (h[i] - h[i - 1]) : 0.0,
                    1e-9 * scale)
            << "the standard force is exact on full and empty faces: " << i << ", " << k;
        EXPECT_EQ(correction[g.at(i, k)], 0.0);
      }
    }
  EXPECT_GE(partly_filled, 12);
  if (rho_light == 0.0) {
    EXPECT_GE(same_row, 10);
  }
}
}  // namespace

TEST(SurfaceRowPressure, PartlyFilledFacesFeelTheHydrostaticForceOnTheirGrains) {
  check(0.0);
  check(0.15);
}

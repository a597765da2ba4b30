// Initial states (Barker & Gray 2017, §5.2 and §7):
//
//   h(x) = h0 + a0 sin(2 pi x / Lx)                                               (7.2)
//   p = rho_* phi g cos(zeta) (h(x) - z)                                          (5.4)
//   u = (2 I_zeta / 3d) sqrt(phi g cos zeta) (h^{3/2} - (h - z)^{3/2})             (5.5)
//
// evaluated at the local height. The volume fraction is the cell average of H(h(x) - z)
// (exact in z, 16-point midpoint in x). The vertical velocity is the discrete integral of the
// continuity equation from the bed, w_{k+1} = w_k - dz (u_{i+1,k} - u_{i,k})/dx, so the
// initial field is divergence free on the grid and kinematically consistent with (7.2). The
// pressure is the discrete hydrostatic balance of the cell densities (equal to (5.4) inside
// the grains), so a layer at rest starts in exact equilibrium. On a moving grid (grid.hpp) u is
// taken relative to it; at t = 0 the grid and the lab coincide.
#include "twod/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "twod/properties.hpp"

namespace granbench::twod {

InitialCondition perturbed_bagnold(const SteadyState& steady, double a0, double Lx) {
  InitialCondition ic;
  const double h0 = steady.h0;
  ic.height = [=](double x) {
    return h0 + a0 * std::sin(2.0 * std::numbers::pi * x / Lx);
  };  // (7.2)
  ic.velocity = [steady, height = ic.height](double x, double z) {
    const double h = height(x);
    return steady.velocity_at_depth(std::min(z, h), h);  // (5.5) at the local depth
  };
  return ic;
}

InitialCondition layer_at_rest(double h0) {
  return {[h0](double) { return h0; }, [](double, double) { return 0.0; }};
}

void hydrostatic_pressure(const Grid& g, const Properties& props, double g_cos_zeta,
                          std::vector<double>& p) {
  p.assign(g.cells(), 0.0);
  for (int i = 0; i < g.nx; ++i) {
    // top half cell, then one face at a time downwards                                (5.4)
    p[g.at(i, g.nz - 1)] = props.rho_w[g.at(i, g.nz)] * g_cos_zeta * 0.5 * g.dz;
    for (int k = g.nz - 1; k > 0; --k)
      p[g.at(i, k - 1)] = p[g.at(i, k)] + props.rho_w[g.at(i, k)] * g_cos_zeta * g.dz;
  }
}

Fields make_initial_state(const Grid& g, const InitialCondition& ic, const SolverParams& params) {
  Fields s(g);
  constexpr int kSub = 16;
  for (int i = 0; i < g.nx; ++i)
    for (int k = 0; k < g.nz; ++k) {
      double sum = 0.0;
      for (int q = 0; q < kSub; ++q) {
        const double x = (i + (q + 0.5) / kSub) * g.dx;
        sum += std::clamp((ic.height(x) - k * g.dz) / g.dz, 0.0, 1.0);
      }
      s.f[g.at(i, k)] = sum / kSub;
    }
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i)  // ic is in the lab frame; the grid's u is relative to it
      s.u[g.at(i, k)] = ic.velocity(i * g.dx, g.zc(k)) - g.frame_speed;
  for (int i = 0; i < g.nx; ++i)
    for (int k = 0; k < g.nz; ++k)  // discrete continuity from the bed (w = 0 there)
      s.w[g.at(i, k + 1)] = s.w[g.at(i, k)] - g.dz * (s.u[g.at(i + 1, k)] - s.u[g.at(i, k)]) / g.dx;
  Properties props(g);
  update_densities(g, s.f, params.rheology, props);
  hydrostatic_pressure(g, props, params.rheology.material.g * std::cos(params.zeta), s.p);
  return s;
}

}  // namespace granbench::twod

// The pressure in eta = mu(I) p / (2|D|) (2.11) at the new time level, without a second solve.
//
// The surface mode's growth rate depends on the phase of the friction's pressure dependence
// (q p' in the linearised stress): eta evaluated at p^n lags the surface by one step, and at cfl
// 0.4 on 32 cells per h0 that alone costs ~20 % of the §7 growth rate (docs/twod-validation.md).
// p^{n+1} is not known before the projection, but its part that follows the surface is: the VOF
// has already moved the surface to h^{n+1}, and the hydrostatic pressure of the two layers,
//
//   p_hs(z; h) = rho_g g cos(zeta) max(h - z, 0) + rho_l g cos(zeta) (Lz - max(h, z)),
//
// (p = 0 at the top of the domain, z = Lz) changes with it. So eta takes
//
//   p_eta = p^n + p_hs(z; h^{n+1}) - p_hs(z; h^n)
//
// column by column, at each cell centre. The dynamic rest d = p - p_hs(h) is extrapolated to
// t^{n+1} (SolverParams::extrapolate_dynamic_viscosity_pressure, the default):
//
//   p_eta = p_hs(h^{n+1}) + d^n + dt (d^n - d^{n-2}) / (t^n - t^{n-2}).
//
// Lagging d was the last first-order error of the §7 growth rate in time (docs/twod-validation.md
// §2). The slope is taken over two steps, not one: the projection's pressure increment feeds
// back into itself through eta, and when that feedback flips sign from step to step (gain G < 0),
// the slope over one step, p^n + r (p^n - p^{n-1}), amplifies it for G < -1/3 (it grew without
// bound within ~60 steps of the §7 case, for the whole pressure and for its dynamic part alike),
// while the slope over two steps is blind to a pattern of period two and keeps the lagged
// evaluation's range, |G| < 1.
#include "twod/viscosity_pressure.hpp"

#include <algorithm>
#include <cmath>

#include "twod/parallel.hpp"

namespace granbench::twod {

namespace {

// The two layers' hydrostatic pressure p_hs(z; h) under a surface at height h.
struct Hydrostatic {
  double g_cos, rho_g, rho_l, Lz;
  Hydrostatic(const Grid& g, const SolverParams& params)
      : g_cos(params.rheology.material.g * std::cos(params.zeta)),
        rho_g(params.rheology.material.bulk_density()),
        rho_l(params.rheology.rho_light),
        Lz(g.Lz) {}
  double operator()(double h, double z) const {
    return rho_g * g_cos * std::max(h - z, 0.0) + rho_l * g_cos * (Lz - std::max(h, z));
  }
};

}  // namespace

double ambient_pressure(const Grid& g, const SolverParams& params, double z) {
  if (!params.rheology.effective_pressure) return 0.0;
  return params.rheology.rho_light * params.rheology.material.g * std::cos(params.zeta) *
         (g.Lz - z);
}

void effective_pressure(const Grid& g, const SolverParams& params, const std::vector<double>& p,
                        std::vector<double>& p_eff) {
  p_eff.resize(p.size());
  parallel_for(g.nz, true, [&](int k) {
    const double ambient = ambient_pressure(g, params, g.zc(k));
    for (int i = 0; i < g.nx; ++i) p_eff[g.at(i, k)] = p[g.at(i, k)] - ambient;
  });
}

void viscosity_pressure(const Grid& g, const SolverParams& params, const std::vector<double>& p,
                        const std::vector<double>& h_before, const std::vector<double>& h_after,
                        std::vector<double>& p_eta) {
  const Hydrostatic hydrostatic(g, params);
  p_eta.resize(p.size());
  parallel_for(g.nz, true, [&](int k) {  // rows in parallel, each entry written once
    const double z = g.zc(k), ambient = ambient_pressure(g, params, z);
    for (int i = 0; i < g.nx; ++i)
      p_eta[g.at(i, k)] =
          p[g.at(i, k)] + (hydrostatic(h_after[i], z) - hydrostatic(h_before[i], z)) - ambient;

  });
}

void viscosity_pressure(const Grid& g, const SolverParams& params, const std::vector<double>& p,
                        const std::vector<double>& h_before, const std::vector<double>& h_after,
                        double t, double dt, DynamicPressureHistory& history,
                        std::vector<double>& p_eta) {
  const Hydrostatic hydrostatic(g, params);
  const std::size_t cells = p.size();
  p_eta.resize(cells);
  if (history.older.size() != cells || history.old.size() != cells) history.levels = 0;
  history.older.resize(cells);
  history.old.resize(cells);
  const bool extrapolate = history.levels >= 2 && t > history.t_older;
  const double weight = extrapolate ? dt / (t - history.t_older) : 0.0;
  // d^n goes into 'older' (d^{n-2} is read first), then the two swap: old = d^n, older = d^{n-1}
  parallel_for(g.nz, true, [&](int k) {
    const double z = g.zc(k), ambient = ambient_pressure(g, params, z);
    for (int i = 0; i < g.nx; ++i) {
      const int c = g.at(i, k);
      const double dynamic = p[c] - hydrostatic(h_before[i], z);
      const double slope_part = extrapolate ? weight * (dynamic - history.older[c]) : 0.0;
      p_eta[c] = hydrostatic(h_after[i], z) + dynamic + slope_part - ambient;
      history.older[c] = dynamic;
    }
  });
  history.older.swap(history.old);
  history.t_older = history.t_old;
  history.t_old = t;
  history.levels = std::min(history.levels + 1, 2);
}

}  // namespace granbench::twod

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
// column by column, at each cell centre. The dynamic rest of p^{n+1} - p^n stays lagged.
// (Extrapolating the whole pressure, p^n + r (p^n - p^{n-1}), was tried first: it feeds the
// projection's pressure increment back into itself through eta and grew without bound within
// ~60 steps of the §7 case.)
#include "twod/viscosity_pressure.hpp"

#include <algorithm>
#include <cmath>

#include "twod/parallel.hpp"

namespace granbench::twod {

void viscosity_pressure(const Grid& g, const SolverParams& params, const std::vector<double>& p,
                        const std::vector<double>& h_before, const std::vector<double>& h_after,
                        std::vector<double>& p_eta) {
  const double g_cos = params.rheology.material.g * std::cos(params.zeta);
  const double rho_g = params.rheology.material.bulk_density(), rho_l = params.rheology.rho_light;
  auto hydrostatic = [&](double h, double z) {
    return rho_g * g_cos * std::max(h - z, 0.0) + rho_l * g_cos * (g.Lz - std::max(h, z));
  };
  p_eta.resize(p.size());
  parallel_for(g.nz, true, [&](int k) {  // rows in parallel, each entry written once
    const double z = g.zc(k);
    for (int i = 0; i < g.nx; ++i)
      p_eta[g.at(i, k)] =
          p[g.at(i, k)] + (hydrostatic(h_after[i], z) - hydrostatic(h_before[i], z));

  });
}

}  // namespace granbench::twod

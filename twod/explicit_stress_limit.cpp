// The implicit part of the linearised mu(I) stress; see explicit_stress_limit.hpp.
#include "twod/explicit_stress_limit.hpp"

#include <algorithm>

#include "twod/parallel.hpp"

namespace granbench::twod {

double lightest_face_density_around_cell(const Grid& g, const Properties& props, int i, int k) {
  return std::min({props.rho_u[g.at(i, k)], props.rho_u[g.at(i + 1, k)], props.rho_w[g.at(i, k)],
                   props.rho_w[g.at(i, k + 1)]});
}

double lightest_face_density_around_corner(const Grid& g, const Properties& props, int i, int k) {
  double rho = std::min(props.rho_w[g.at(i - 1, k)], props.rho_w[g.at(i, k)]);
  if (k > 0) rho = std::min(rho, props.rho_u[g.at(i, k - 1)]);  // the u-face below the corner
  if (k < g.nz) rho = std::min(rho, props.rho_u[g.at(i, k)]);   // and the one above it
  return rho;
}

void implicit_viscosities(const Grid& g, const Properties& props, double dt,
                          std::vector<double>& implicit_c, std::vector<double>& implicit_n) {
  const double h = std::min(g.dx, g.dz);
  const double h2_over_dt = h * h / dt;
  implicit_c.resize(g.cells());
  implicit_n.resize(g.corners());
  parallel_for(g.nz, true, [&](int k) {  // rows in parallel, each entry written once
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t c = g.at(i, k);
      const double rho = lightest_face_density_around_cell(g, props, i, k);
      implicit_c[c] = std::max(props.eta_c_tangent[c], props.eta_c[c] - rho * h2_over_dt);
    }
  });
  parallel_for(g.nz + 1, true, [&](int k) {
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t n = g.at(i, k);
      const double rho = lightest_face_density_around_corner(g, props, i, k);
      implicit_n[n] = std::max(props.eta_n_tangent[n], props.eta_n[n] - rho * h2_over_dt);
    }
  });
}

}  // namespace granbench::twod

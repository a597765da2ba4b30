// Initial states of the depth-averaged model on its periodic grid (cell centres x_j):
//
//   sine       h = h0 + a0 sin(2 pi m x / Lx), u = u_bar(h) of the steady state at the local depth,
//              (2 I_zeta / 5d) sqrt(phi g cos zeta) h^{3/2}                       (7.2), §7
//   eigenmode  the normal mode (7.10) of the linearised equations: in the scales of (7.13),
//              h = 1 + eps Re(e^{i k x}), u = 1 + eps Re(u_t e^{i k x}) with, from (7.7),
//              u_t = -(lambda + i k)/(i k),                                        (7.7), (7.10)
//              eps = a0/h0, k = 2 pi m h0/Lx, lambda the chosen root of the (chi-generalised)
//              dispersion relation (7.11), which the caller supplies
//              (analysis/theory/dispersion.hpp).
//
// Optional noise: uniform random heights of amplitude noise*h0 (zero mean, so the mass is that of
// the noiseless state), fixed seed. Values at the cell centres (second-order cell averages).
#pragma once

#include <complex>
#include <vector>

#include "depthavg/params.hpp"
#include "depthavg/rhs.hpp"

namespace granbench::depthavg {

// U = (h_j, h_j u_j) interleaved. lambda_hat is required for InitKind::Eigenmode.
std::vector<double> initial_state(const Rhs& rhs, const InitialParams& init,
                                  std::complex<double> lambda_hat = {0.0, 0.0});

}  // namespace granbench::depthavg

// Exact 2D linear stability of steady uniform mu(I) chute flow (Bagnold state (5.4)-(5.5)) under
// the incompressible equations (2.9)-(2.11) with a free surface; docs/linear-theory.md derives it.
//
// Perturbations ~ exp(i k x + lambda t): growth rate Re(lambda), phase speed -Im(lambda)/k
// (docs/design.md §5). The scaled problem (length h0, speed u_bar_0, time h0/u_bar_0) depends on
// F, tan(zeta) and Gamma = I_zeta mu'(I_zeta) only. Its long-wave expansion (Benney type, derived
// in docs/linear-theory.md) gives
//
//   lambda_hat = -(5/2) i k_hat + c2 k_hat^2 + O(k_hat^3),
//   c2 = (5/(2 Gamma)) ((5/8) F^2 - 2/5 + (3/5) mu q),   q = mu - Gamma/2   (3.3b),
//
// so long waves grow for F > F_c = sqrt((8/25)(2 - 3 mu q)) (F_c = 0.608 at 28.5 deg with the
// regularised curve; the depth-averaged value is 2/3 for chi = 1).
//
// The surface mode is found by continuation in k from the kinematic wave lambda = -(5/2) i k of the
// long-wave limit; every other mode with Re(lambda) > 0 is listed as well. Each reported mode is
// recomputed at a second, finer resolution as a convergence check.
#pragma once

#include <complex>
#include <limits>
#include <optional>
#include <vector>

#include "analysis/linear2d/base_state.hpp"
#include "analysis/linear2d/light_layer.hpp"
#include "analysis/linear2d/operator.hpp"
#include "analysis/linear2d/spectrum.hpp"
#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"

namespace granbench {

namespace linear2d {

// dq/dh of the steady flux q ~ h^{5/2} (Bagnold) or h^3 (Nusselt), in units of u_bar_0.
double kinematic_speed(const LinearBaseState& b);
// c2 above (Bagnold state only).
double long_wave_growth_coefficient(const LinearBaseState& b);
// F_c = sqrt((8/25)(2 - 3 mu q)); 0 if long waves grow at any F.
double critical_froude_2d(double mu, double Gamma);

// Finite eigenvalues at k_hat with N Chebyshev intervals, by decreasing real part.
std::vector<std::complex<double>> spectrum(const LinearBaseState& b, double k_hat, int N,
                                           VerticalMap map = VerticalMap::SquareRoot);

struct ContinuationOptions {
  int N = 16;             // resolution used along the path
  double k_start = 0.02;  // start of the path in k_hat (long-wave limit)
  double step_ratio = 1.3;
};
// Eigenvalue of the surface mode at k_hat, traced from the kinematic wave, at resolution N.
std::complex<double> surface_mode_eigenvalue(const LinearBaseState& b, double k_hat, int N,
                                             VerticalMap map = VerticalMap::SquareRoot,
                                             const ContinuationOptions& path = {});

// The 2D cutoff: the k_hat where the surface mode's growth rate, positive for long waves,
// crosses zero (shorter waves decay), at resolution N in `map`, to 1e-10 in k_hat. The branch is
// followed from path.k_start in steps of 20 %, then the crossing is bracketed by Brent's method.
// Empty when the surface mode decays at path.k_start already (F below F_c) or still grows at
// k_max.
std::optional<double> surface_mode_cutoff_k_hat(const LinearBaseState& b, int N,
                                                VerticalMap map = VerticalMap::SquareRoot,
                                                const ContinuationOptions& path = {},
                                                double k_max = 30.0);

// The scaled wavenumber k_hat = 2 pi h0 / Lx of (7.13b); Lx > 0 [m].
double scaled_wavenumber(const SteadyState& s, double Lx);

// The surface mode at k_hat with its eigenvector at resolution N >= 4, without the rest of the
// spectrum: the mode linear_stability_2d reports, at a fraction of its cost (for seeding).
Eigenpair surface_mode(const LinearBaseState& b, double k_hat, int N, VerticalMap map,
                       const ContinuationOptions& path = {});

// The surface branch over increasing k_hat values (continued point to point), with the largest
// growth rate among the other modes at each k_hat (NaN if none is finite).
struct BranchPoint {
  double k_hat = 0.0;
  std::complex<double> surface;    // lambda_hat of the surface mode
  double other_max_growth = 0.0;   // max Re(lambda_hat) over the remaining modes
  double other_phase_speed = 0.0;  // -Im/k_hat of that mode
};
std::vector<BranchPoint> surface_branch(const LinearBaseState& b, const std::vector<double>& k_hat,
                                        int N, const ContinuationOptions& path = {});

}  // namespace linear2d

struct Linear2DOptions {
  int N = 32;        // Chebyshev intervals (N + 1 nodes)
  int N_check = 48;  // second resolution for the convergence check (none if <= N)
  linear2d::VerticalMap map = linear2d::VerticalMap::SquareRoot;
  linear2d::ContinuationOptions path;
  // The light fluid of the 2D solver above the grains (analysis/linear2d/light_layer.hpp); absent:
  // the stress-free surface only. Its modes are computed with N (and N_check) points in the fluid
  // too.
  std::optional<linear2d::LightLayer> light_layer;
};

struct Linear2DMode {
  std::complex<double> lambda_hat;  // scaled (7.13)
  double growth_rate = 0.0;         // Re(lambda) [1/s]
  double phase_speed = 0.0;         // -Im(lambda)/k [m/s]
  bool surface = false;             // continued from the kinematic wave
  std::complex<double> lambda_hat_check{std::numeric_limits<double>::quiet_NaN(), 0.0};
  double relative_difference = std::numeric_limits<double>::quiet_NaN();  // |l(N)-l(Nc)|/|l(Nc)|
};

// The modes of the grains under the light fluid. Each unstable stress-free mode is continued to
// the layer (rho_l, eta_l raised together from 1e-8 of their values), so `continued[i]` is the
// counterpart of `Linear2DResult::unstable[i]` and `surface` that of the surface mode.
struct Linear2DLightLayerResult {
  linear2d::LightLayer layer;
  linear2d::LightLayerScaled scaled;
  Linear2DMode surface;
  std::vector<Linear2DMode> continued;
  std::vector<Linear2DMode> unstable;  // all modes of the layer with growth > 0, largest first
};

struct Linear2DResult {
  double Lx = 0.0;
  double k_hat = 0.0;
  int N = 0;
  int N_check = 0;
  linear2d::LinearBaseState base;
  Linear2DMode surface;
  std::vector<Linear2DMode> unstable;  // all modes with growth > 0, largest first
  linear2d::Eigenpair surface_pair;    // scaled eigenvector of the surface mode at N
  std::optional<Linear2DLightLayerResult> light_layer;  // with Linear2DOptions::light_layer
};

// The 2D linear stability of the Bagnold state `s` of `curve` at wavelength Lx [m].
Linear2DResult linear_stability_2d(const SteadyState& s, const MuCurve& curve, double Lx,
                                   const Linear2DOptions& opt = {});

}  // namespace granbench

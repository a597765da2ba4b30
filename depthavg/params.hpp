// Parameters of the depth-averaged model (Barker & Gray 2017, (7.3)-(7.5)) and of its numerics:
// the grid, the momentum shape factor chi (momentum flux chi h u^2 in (7.4); docs/design.md §10),
// the slope reconstruction, the CVODE tolerances and the run's output interval. Plain value structs
// with defaults; the physical base state (slope, depth, curve) comes from common/steady_state.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace granbench::depthavg {

// Slope reconstruction of the cell averages at the faces. Central is the unlimited centred slope
// (second order, for clean linear-regime measurements); the limiters keep h positive and the
// solution free of new extrema for nonlinear rollwaves. Van Albada's limiter is smooth (no kinks
// in dU/dt), which suits the implicit BDF integrator; minmod and MC are piecewise linear in the
// differences, so CVODE's error control sees kinks and takes much smaller steps.
enum class Reconstruction { Central, Minmod, MC, VanAlbada };
std::string_view reconstruction_name(Reconstruction r);
// "central", "minmod", "mc", "vanalbada"; throws std::invalid_argument otherwise.
Reconstruction parse_reconstruction(std::string_view name);

struct SpaceParams {
  double Lx = 0.08;      // domain length [m], periodic
  std::size_t nx = 256;  // number of cells
  double chi = 1.0;      // momentum shape factor: 1 the paper's, 5/4 Bagnold's
  Reconstruction reconstruction = Reconstruction::Central;
  bool viscous = true;           // the term d/dx(nu h^{3/2} du/dx) of (7.4)
  double h_dry_fraction = 1e-6;  // depth (as a fraction of h0) below which u is desingularised
  double frame_speed = 0.0;      // speed c of the computational frame x' = x - c t [m/s] (rhs.hpp)
};

// How CVODE solves the Newton systems (I - gamma J) x = b of its BDF steps (cvode_integrator.hpp).
// Direct: modified Newton with J the coloured difference-quotient Jacobian, factored exactly
// (periodic_block_band.hpp) and refreshed when CVODE asks for it. KrylovBand: SPGMR, that
// factorisation as left preconditioner, Jacobian-vector products by difference quotients.
// Krylov: SPGMR without a preconditioner (near the CFL limit I - gamma J is close to the
// identity and GMRES converges anyway).
enum class LinearSolver { Direct, KrylovBand, Krylov };

struct IntegratorParams {
  double rtol = 1e-6;
  double atol = 1e-10;       // absolute tolerance, scaled per component (h in m, hu in m^2/s)
  long max_steps = 2000000;  // per output interval
  // CVODE is called for at most this many internal steps at a time; between calls the run looks
  // at the stop flag and at a stall (cvode_integrator.hpp). The steps are those of one call.
  long steps_per_call = 2000;
  // BDF order limit. Orders 3-5 are not A-stable: near the imaginary axis, where a hyperbolic
  // semi-discretisation's eigenvalues lie, they are unstable over a band of steps, and CVODE then
  // holds the step at that band whatever the tolerance (the rollwave of `run` took 5 900-7 300
  // steps at rtol 1e-4 .. 1e-6). Order 2 is A-stable and its steps grow as the tolerance loosens,
  // so it is the choice at moderate tolerances; at tight ones (linear measurements) the accuracy
  // limit is far below that band and order 5 is cheaper. docs/performance.md has the measurements.
  int max_order = 5;
  LinearSolver linear_solver = LinearSolver::Direct;
  double eps_lin = 0.05;  // CVODE's linear-solver tolerance factor (the Krylov solvers only)
};

enum class InitKind { Sine, Eigenmode };

struct InitialParams {
  InitKind kind = InitKind::Sine;
  double a0 = 2e-4;    // perturbation amplitude of h [m] (7.2)
  int mode = 1;        // number of wavelengths in the domain
  double noise = 0.0;  // amplitude of random noise in h, as a fraction of h0
  std::uint64_t seed = 1;
};

struct OutputParams {
  double t_end = 10.0;   // [s]
  double dt_out = 0.01;  // sampling interval of the SurfaceSeries [s]
};

}  // namespace granbench::depthavg

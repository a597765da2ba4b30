// Parameters of the 2D two-phase mu(I) solver (value types with defaults, passed by const ref).
//
// The regularisation constants of the granular viscosity (docs/design.md §8) are case inputs and
// are written into every output: the floor on |D|, the cap eta_max (2 Pa s as in Gerris' runs), the
// floor eta_min, and the rule that mixes granular and light-fluid viscosities in interface cells.
#pragma once

#include "common/material.hpp"
#include "common/mu_curves.hpp"
#include "twod/parallel.hpp"

namespace granbench::twod {

// Viscosity in cells holding both phases (f = granular fraction):
//   Arithmetic  eta = f eta_g + (1 - f) eta_l     (default: with rho = f rho_g + (1-f) rho_l the
//               grains in a partly filled cell keep their kinematic viscosity eta_g/rho_g)
//   Harmonic    1/eta = f/eta_g + (1 - f)/eta_l   (Gerris' main runs; the light phase dominates,
//               so grains in interface cells move with the light fluid's viscosity. Measured in
//               this solver: a steady Bagnold layer at 24 deg on a 16-cell-deep grid leaves its
//               x-uniform state within ~1 s (a surface mode growing at ~23 1/s), which the
//               arithmetic rule does not do; the rollwave at 8 cells per h0 grows at +2.1 1/s
//               with it against -3.0 1/s with the arithmetic rule.)
enum class ViscosityMixing { Harmonic, Arithmetic };

// Pressure at which the granular viscosity of interface cells and corners is evaluated:
//   CellAverage   the cell-centre p (corners: mean of the four cells), as everywhere else. At a
//   corner on a flat surface lying on a cell face this p is
//                 rho g cos(zeta) dz/4 > 0 while the weight above it is ~0, so
//                 mu(I) p = tau needs I -> 0: eta hits eta_max and the corner is a plug that
//                 locks the top half-cell of grains to the light fluid (docs/twod-validation.md).
//   Extrapolated  the overburden: p interpolated linearly between the nearest fully granular
//                 cell centre below and the light fluid's p at the column's surface height
//                 h = sum f dz (corners: mean of the two columns), taken at the corner or at the
//                 centroid of the cell's granular part; and interface corners are granular
//                 (unmixed eta_g) below h and light fluid above it. Assumes a surface that is a
//                 graph h(x). Removes the plug; the steady flux no longer depends on where the
//                 surface sits in its cell. The default: the plug of CellAverage costs 5-8 % of
//                 the §7 growth rate. It lowers the max-norm order of the steady Bagnold test
//                 (top granular row) from > 1.4 to ~1; the L1 order stays ~2.
enum class InterfacePressure { CellAverage, Extrapolated };

// Preconditioner of the conjugate-gradient solves (spd_solver.hpp, pcg.hpp):
//   Multigrid      geometric V-cycle with z-line smoothing (pressure only; the default there)
//   LineRelaxation symmetric z-line Gauss-Seidel (the default for the viscous step)
//   StaleCholesky  the exact sparse Cholesky factor of an earlier matrix, refreshed when the
//                  iteration count rises
//   Direct         a fresh Cholesky factorisation every solve
//   Jacobi         the diagonal
enum class LinearSolverKind { Multigrid, LineRelaxation, StaleCholesky, Direct, Jacobi };

struct Rheology {
  Material material;
  CurveKind curve = CurveKind::Regularised;
  double h0_for_curve = 4e-3;  // only the Holyoake curve (6.1) depends on depth
  double eta_max = 2.0;        // cap on the granular viscosity [Pa s]
  double eta_min = 1e-3;       // floor on the granular viscosity [Pa s]
  double D_min = 1e-6;         // floor on |D| [1/s]
  // The light fluid stands in for the stress-free surface of the theory (docs/design.md §7): the
  // lighter and less viscous it is, the closer the surface is to stress free. At 1.5 kg m^-3
  // and 1e-3 Pa s (air-like, the paper's) its drag on the surface cost ~20 % of the §7 growth
  // rate, because 1e-3 Pa s is the granular tangent viscosity one cell below the surface at 32
  // cells per h0. The default is 1e-6 of the grains' density (since 7 December, fiftieth
  // session; 1e-5 before): near the 2D cutoff, where the growth is small, a ten times heavier
  // fluid than 1e-5 moved the growth by +2.9 % (1.5 cm) and +1.3 % (1.4 cm), and the issue asks
  // <= 1 %; ten times heavier than 1e-6 (the former default) moves it by +0.4 % and +0.6 %, ten
  // times lighter by -0.04 % and -0.06 %, and at 8 cm (both properties or either alone) by at
  // most 0.012 % (docs/twod-validation.md, "Where it stands"). The 10-s sine rollwaves at 8 and
  // 12 cm and the steep-flow test run with it, and it takes 4-6 % fewer solver iterations.
  double rho_light = 0.0015;  // light-fluid density [kg m^-3]
  double eta_light = 1e-6;    // light-fluid viscosity [Pa s]
  // true (default since 4 December, twenty-first session): every face feels the ambient
  // pressure gradient along the slope, -rho_light g sin(zeta), the light fluid's hydrostatic
  // gradient along x that a periodic domain cannot carry as a pressure difference
  // (viscous_step.cpp). The light fluid at rest above a steady layer is then in balance and moves
  // with the surface; the grains feel their weight less the light fluid's (buoyancy, 1e-6 of it).
  // false: gravity alone drives the light layer along the slope, a stream 0.06 m/s faster than
  // the surface at the lid whose shear (28 1/s) made the growth depend on the seed's amplitude
  // with the surface on a cell face (docs/twod-validation.md §4, "Wisps at a face").
  bool ambient_pressure_gradient = true;
  // true (the default since 5 December, twenty-seventh session): the pressure in mu(I) (2.8,
  // 2.11) is the grains' effective pressure, the mixture's pressure less the light fluid's
  // hydrostatic pressure rho_light g cos(zeta) (Lz - z), which the fluid in the pores carries
  // (Terzaghi's effective stress). The held light layer (ambient_pressure_gradient) puts its
  // weight on the grains' surface as a normal load with no shear traction; in mu(I) that
  // overburden lowers mu within the surface row, and a ten times heavier light fluid moved the
  // growth by +1 % at 64 cells per h0, with a second wave that neither linear theory has. With
  // the effective pressure both go, and the grains see the paper's stress-free surface
  // (docs/twod-validation.md, "Where it stands"). false: the mixture's pressure, as in Gerris.
  bool effective_pressure = true;
  ViscosityMixing mixing = ViscosityMixing::Arithmetic;
  InterfacePressure interface_pressure = InterfacePressure::Extrapolated;
  // Newtonian granular phase instead of mu(I) (used by the Nusselt-film validation): eta_g =
  // newtonian_eta when > 0.
  double newtonian_eta = 0.0;
  // true (the default since 2 December, eighth session): the granular corner below a partly
  // filled surface row takes its shear rate over the distance to the centroid of the row's
  // grains, (1 + f) dz / 2 (properties.cpp). It cuts the growth rate's dependence on where the
  // surface sits in its cell from 4.9 % to 2.2 % at 32 cells per h0 (12.8 % to 3.1 % at 16,
  // 1.3 % to 0.7 % at 64) at the same mean over the cell (docs/twod-validation.md §4). Since the
  // twenty-first session the surface row's own strain rate takes that shear of its two lower
  // corners, not the mean of four corners with the light fluid's two (properties.cpp).
  bool surface_row_shear_spacing = true;
};

struct SolverParams {
  Rheology rheology;
  double zeta = 0.0;     // slope angle [rad]
  double cfl = 0.4;      // advective Courant number per direction (< 0.5 for the VOF)
  double dt_max = 1e-3;  // [s]
  // Cap of the first step [s]; 0: none, the CFL step of the initial state. Every seeded run
  // starts from the steady flow, whose CFL step holds from the first step on (a 1e-5 s start
  // grown by dt_growth added 27 steps to the first 3 ms, 8 % of the Gerris comparison's 0.1 s;
  // the §7 growth rate moved by under 1e-6 of itself, docs/twod-validation.md has the rest). A
  // flow at rest gets dt_max, a step that the CFL limit and dt_growth then follow.
  double dt_initial = 0.0;
  double dt_growth = 1.1;           // largest ratio dt_{n+1}/dt_n
  double solver_tolerance = 1e-10;  // relative residual of the projection (sets div u, mass)
  // The viscous solve stops at ||b - A u*|| <= viscous_tolerance ||b - A u^n||: relative to the
  // change the step makes, not to ||b|| (which holds rho u^n / dt and hid a small wave's change),
  // but never looser than 1e-8 ||b|| (a large change, a splash; viscous_stop_tolerance in
  // viscous_step.hpp).
  double viscous_tolerance = 1e-4;
  LinearSolverKind viscous_solver = LinearSolverKind::LineRelaxation;
  LinearSolverKind pressure_solver = LinearSolverKind::Multigrid;
  double velocity_limit = 50.0;  // |u| above this is reported as divergence [m/s]
  // The stress at the new level without a second solve (solver.cpp, viscous_step.cpp):
  //   viscosity_tangent: tau^{n+1} = tau(D^n, p*) + C^n : (D^{n+1} - D^n) with the consistent
  //     tangent C of the strain-rate dependence (false: eta from u^n, lagged one step);
  //   hydrostatic_viscosity_pressure: p* = p^n plus the hydrostatic change of this step's
  //     surface move (viscosity_pressure.cpp; false: p* = p^n, lagged one step).
  // Each lag is a first-order time error of the growth rate (docs/twod-validation.md).
  bool viscosity_tangent = true;
  bool hydrostatic_viscosity_pressure = true;
  //   extrapolate_dynamic_viscosity_pressure: p* also takes the dynamic rest of p, extrapolated
  //     to t^{n+1} along its slope over the last two steps (viscosity_pressure.hpp; false: the
  //     dynamic rest lagged one step, a first-order error, 0.0028 s^-1 of the §7 growth at cfl
  //     0.4).
  bool extrapolate_dynamic_viscosity_pressure = true;
  // true (default): the u-faces of a partly filled surface row feel the hydrostatic pressure force
  // on the grains they hold, not the half-slope force of the interface cells' centroid pressure
  // (surface_row_pressure.cpp). It cuts the growth rate's dependence on where the surface sits in
  // its cell from 11 % to 3 % at 32 cells per h0 (docs/twod-validation.md §4). false: the
  // standard MAC force.
  bool surface_row_pressure = true;
  // true (default since 4 December, twenty-first session): the w-faces just below and above a
  // partly filled surface row feel the x-derivative of the shear stress over the heights its
  // grains fill, not over the stencil's dz (surface_row_shear.cpp). It removes a pressure offset
  // below the surface row that changed sign with the surface's place in its cell, and with it the
  // growth rate's fall across the cell; with the ambient pressure gradient (Rheology) the §7
  // growth varies by 0.8 % between the surface on a face and at 1/4, 1/2, 3/4 of its cell at 32
  // cells per h0, against 3.6 % without either (docs/twod-validation.md §4). false: the stencil's.
  bool surface_row_shear = true;
  // Passes of predictor + projection per step. 1: one solve. n > 1: each further pass recomputes
  // eta from the previous pass's u^{n+1}, p^{n+1} (Picard), so eta is taken at the new time level
  // to the accuracy of the iteration (about n times the cost).
  int viscosity_passes = 1;
  // Time integration of the stress, pressure and gravity (the non-advective part F of the step).
  // true: second-order BDF2 on the increment, u^{n+1} - u~ = (dt/a0) F^{n+1} + (a2/a0) delta^n,
  // with u~ the advected velocity, delta^n the previous step's non-advective increment carried
  // with the material, a0 = (1+2r)/(1+r), a2 = r^2/(1+r), r = dt_n/dt_{n-1} (solver.cpp). false:
  // backward Euler, first order: the section 7 growth 0.6 % lower at cfl 0.4
  // (docs/twod-validation.md §10).
  bool stress_bdf2 = true;
  // What the momentum predictor takes from the previous step's pressure p^n (viscous_step.cpp).
  // true (default): the acceleration grad p^n / rho^n it gave, through the implicit stress
  // solve, and the rest of dt grad p^n / rho^{n+1} added after it; a face the interface has
  // emptied then keeps its light fluid at the acceleration the grains had. false: the force
  // grad p^n through the solve, which drives such a face's light fluid at up to 1e5 g; the
  // stress spreads that into the grains beside it, and the 12 cm sine rollwave diverged at
  // 6.5 s (docs/twod-validation.md §10, last subsection). Identical where no face's density
  // changes.
  bool predictor_pressure_acceleration = true;
  // With predictor_pressure_acceleration: the largest acceleration grad p^n / rho^{n+1} the
  // predictor's stress solve carries on a face, in units of g; the rest goes to u* after the
  // solve, like an emptied face's (viscous_step.cpp). Gravity and the bulk flow's accelerations
  // (U^2/h0 ~ 37 g in the section 7 flow) stay below it: the linear runs never reach it. A film
  // of light fluid between grains, whose face carries the grains' pressure gradient, sits at
  // ~1e5 g; in nonlinear waves some faces at fronts exceed it too. 0: no limit.
  double predictor_acceleration_limit = 100.0;
  // The velocity that moves the interface (and carries the momentum's mass fluxes): true: the
  // mid-step extrapolation u^n + (r/2)(u^n - u^{n-1}), divergence-free as both levels are (the
  // default since eta's dynamic pressure is extrapolated too: with that alone the interface's
  // lag is left uncancelled, and the growth falls as the step shrinks; docs/twod-validation.md
  // §2); false: u^n, a first-order lag of the surface's kinematic condition.
  bool interface_midstep_velocity = true;
  bool advect_momentum = true;
  // Time integration of the velocity form (consistent_momentum = false): true = second-order
  // Adams-Bashforth, (1 + r/2) A^n - (r/2) A^{n-1} with r = dt_n/dt_{n-1} the ratio of the steps
  // actually taken; false = forward Euler (u^n . grad u^n), whose anti-diffusion (U^2 dt/2) d2/dx2
  // makes the weakly damped surface-layer shear modes (lambda ~ 6 mm) grow
  // (docs/twod-validation.md).
  bool advection_ab2 = true;
  // What carries momentum across the faces. true (default): the mass fluxes of the step's VOF
  // advection (consistent_momentum_advection in momentum_advection.hpp), one step with
  // time-centred face values (no forward-Euler anti-diffusion, no Adams-Bashforth); a parcel of
  // grains keeps its momentum as it crosses faces that held light fluid. false: the velocity
  // (the advective form, with advection_ab2). With the velocity form a droplet of grains thrown
  // off a steep front takes the light fluid's velocity of every face it moves into, rides the
  // light fluid's updraft to the open top, and the run diverges there (docs/twod-validation.md
  // §8); on the linear §7 check the two differ by 0.1-0.2 %.
  bool consistent_momentum = true;
  // The consistent transport's face values centred in time across the face too (true, default):
  // each face value also moves by -(dt/2) V_t dq/dt_t, the transport along the face by the
  // velocity there (the transverse term of Colella's corner transport and of Bell, Colella &
  // Glaz's face values; momentum_advection.cpp). Without it the face values lag by half a step in
  // the other direction, a first-order error that travels with the wave over the grid: the
  // section 7 growth moved by 0.0065 and 0.0034 per halving of the step (cfl 0.4 to 0.1), with it
  // by 0.0024 and 0.0011 (docs/twod-validation.md §10).
  bool advection_transverse_terms = true;
  bool advect_interface = true;
  // Threads of the solver's loops (parallel.hpp); results do not depend on it. The
  // default is the thread count of the thread that makes these parameters (OMP_NUM_THREADS, or
  // granbench --threads on the command's thread), so that a run handed to another std::thread
  // (compare, sweep --jobs, case --jobs) keeps it: the setting belongs to each thread.
  int threads = thread_count();
};

}  // namespace granbench::twod

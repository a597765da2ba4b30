// Time integration of dU/dt = F(U) (rhs.hpp) with SUNDIALS CVODE: variable-order BDF, Newton
// iteration, tolerances as inputs. The only file that talks to SUNDIALS; the SUNDIALS types stay
// behind a private implementation.
//
// The Newton systems (I - gamma J) x = b (IntegratorParams::linear_solver):
// - Direct (the default): J by coloured difference quotients. Each cell's derivative depends on
//   cells j-2 .. j+2, so cells 5 or more apart (cyclic distance) can be perturbed together; about
//   10 evaluations of F give the whole periodic Jacobian, wrap-around included. I - gamma J is
//   factored exactly (periodic_block_band.hpp) and handed to CVODE as a direct linear solver of our
//   own (a SUNLinearSolver of type DIRECT, with an opaque SUNMatrix: CVODE only passes it back).
//   CVODE's modified Newton then reuses J over many steps (it asks for a fresh one after a
//   convergence failure or 51 steps) and refactors when gamma changes by 30 %; one Newton
//   iteration costs one F and one block solve. No Krylov vectors, no Jacobian-vector products.
// - KrylovBand: SPGMR with the same factorisation as left preconditioner (the former default:
//   about 2 linear iterations per Newton iteration, each a difference-quotient J v, a
//   preconditioner solve and Gram-Schmidt dot products).
// - Krylov: SPGMR unpreconditioned.
//
// Mass: F conserves the total of h exactly (flux form), so the columns of J sum to zero over the
// h rows and 1_h^T (I - gamma J) = 1_h^T; the exact inverse keeps that, and the Newton corrections
// change the total mass only at round-off.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <span>
#include <string>

#include "depthavg/params.hpp"
#include "depthavg/rhs.hpp"

namespace granbench::depthavg {

struct CvodeStats {
  long steps = 0;
  long rhs_evals = 0;           // by CVODE itself
  long rhs_evals_jtimes = 0;    // difference-quotient Jacobian-vector products
  long rhs_evals_jacobian = 0;  // coloured difference-quotient Jacobian
  long jacobian_evals = 0;      // coloured Jacobians built (either solver)
  long linear_solves = 0;       // factorised solves (Direct) or preconditioner solves (Krylov)
  long linear_iterations = 0;   // Krylov only
  long nonlinear_iterations = 0;
  long error_test_failures = 0;
  long nonlinear_convergence_failures = 0;
  int last_order = 0;
  double last_step = 0.0;
  long total_rhs_evals() const { return rhs_evals + rhs_evals_jtimes + rhs_evals_jacobian; }
};

// What ends an advance early besides CVODE's own failures. CVODE is called in chunks of at most
// IntegratorParams::steps_per_call internal steps (the steps are the same as in one call: CVODE
// resumes where it returned), and between chunks the stop flag and the step count are looked at, so
// that Ctrl-C is seen within a fraction of a second and an integration whose steps have collapsed
// (a shock or a dry bed the grid no longer resolves) is caught after stall_steps instead of
// IntegratorParams::max_steps: two million steps took five minutes on 256 cells.
struct AdvanceLimits {
  const std::atomic<bool>* stop = nullptr;  // raised: return with `interrupted` after the chunk
  long stall_steps = 0;  // more internal steps than this in one advance: `stalled` (0: none)
};

struct AdvanceResult {
  bool ok = true;
  double t = 0.0;            // time reached
  std::string message;       // CVODE's message (or the step limit's) when !ok
  std::size_t worst = 0;     // the component that was not finite, or else the one with the
                             // largest weighted local error estimate
  bool nonfinite = false;    // worst names a non-finite value of U or F(U)
  bool interrupted = false;  // the stop flag ended the advance before t_out (ok stays true)
  bool stalled = false;      // AdvanceLimits::stall_steps ended it (ok is false)
  long steps = 0;            // internal steps of this advance
  double last_step = 0.0;    // the size of the last of them [s]
};

class CvodeIntegrator {
 public:
  // abs_scale[i] multiplies params.atol for component i (h in m, q in m^2/s); positive_mask[i]
  // (non-zero) asks CVODE to keep component i strictly positive.
  CvodeIntegrator(const Rhs& rhs, std::span<const double> U0, const IntegratorParams& params,
                  std::span<const double> abs_scale, std::span<const double> positive_mask);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  AdvanceResult advance_to(double t_out, const AdvanceLimits& limits = {});
  std::span<const double> state() const;
  double time() const;
  CvodeStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace granbench::depthavg

// Time integration of dU/dt = F(U) (rhs.hpp) with SUNDIALS CVODE: variable-order BDF, Newton
// iteration with the SPGMR Krylov solver (left preconditioning), tolerances as inputs. The only
// file that talks to SUNDIALS; the SUNDIALS types stay behind a private implementation.
//
// Preconditioner: P = I - gamma J_band, with J_band the Jacobian of F by coloured difference
// quotients. Each cell's derivative depends on cells j-2 .. j+2, so cells 5 or more apart (cyclic
// distance) can be perturbed together; about 10 evaluations of F give the whole periodic Jacobian.
// The periodic wrap-around couples the first and last cells, which a band matrix cannot hold:
// those entries are added to the diagonal cell's entry of the same column instead of dropped, so
// P keeps the column sums of J, hence the total mass, and the Newton corrections stay conservative.
// P is held as 2x2 blocks, one per pair of cells within the stencil, and factored by block LU
// without pivoting (block_band.hpp): the same P as a band LU, at a fraction of the solve cost.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>

#include "depthavg/params.hpp"
#include "depthavg/rhs.hpp"

namespace granbench::depthavg {

struct CvodeStats {
  long steps = 0;
  long rhs_evals = 0;                 // by CVODE itself
  long rhs_evals_jtimes = 0;          // difference-quotient Jacobian-vector products
  long rhs_evals_preconditioner = 0;  // coloured difference-quotient band Jacobian
  long linear_iterations = 0;
  long preconditioner_evals = 0;
  long preconditioner_solves = 0;
  long nonlinear_iterations = 0;
  long error_test_failures = 0;
  long nonlinear_convergence_failures = 0;
  int last_order = 0;
  double last_step = 0.0;
  long total_rhs_evals() const { return rhs_evals + rhs_evals_jtimes + rhs_evals_preconditioner; }
};

struct AdvanceResult {
  bool ok = true;
  double t = 0.0;          // time reached
  std::string message;     // CVODE's message when !ok
  std::size_t worst = 0;   // the component that was not finite, or else the one with the
                           // largest weighted local error estimate
  bool nonfinite = false;  // worst names a non-finite value of U or F(U)
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

  AdvanceResult advance_to(double t_out);
  std::span<const double> state() const;
  double time() const;
  CvodeStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace granbench::depthavg

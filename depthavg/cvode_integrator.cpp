// The CVODE glue (BDF; Newton systems by our exact periodic block-band solver or by SPGMR). See
// cvode_integrator.hpp.
#include "depthavg/cvode_integrator.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "depthavg/periodic_block_band.hpp"

namespace granbench::depthavg {

namespace {

// Groups of cells whose stencils (j-r .. j+r) do not overlap on the periodic grid: any two cells
// of a group are at cyclic distance >= 2r+1. Greedy, in index order.
std::vector<std::vector<std::size_t>> colour_cells(std::size_t nx, std::size_t r) {
  const std::size_t sep = 2 * r + 1;
  std::vector<std::vector<std::size_t>> groups;
  std::vector<bool> done(nx, false);
  std::size_t remaining = nx;
  while (remaining > 0) {
    std::vector<std::size_t> g;
    for (std::size_t c = 0; c < nx; ++c) {
      if (done[c]) continue;
      const bool fits = std::all_of(g.begin(), g.end(), [&](std::size_t o) {
        const std::size_t d = c - o;  // c > o
        return std::min(d, nx - d) >= sep;
      });
      if (fits) g.push_back(c);
    }
    for (std::size_t c : g) done[c] = true;
    remaining -= g.size();
    groups.push_back(std::move(g));
  }
  return groups;
}

}  // namespace

struct CvodeIntegrator::Impl {
  const Rhs& rhs;
  std::size_t n;
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, atol = nullptr, constraints = nullptr, ftmp = nullptr, ytmp = nullptr,
           ewt = nullptr, ele = nullptr;
  void* mem = nullptr;
  SUNLinearSolver linear_solver = nullptr;
  SUNMatrix opaque_matrix = nullptr;  // Direct: the handle CVODE passes back (P is the content)
  PeriodicBlockBandMatrix J, P;       // the Jacobian, and the factorisation of I - gamma J
  std::vector<std::vector<std::size_t>> groups;
  std::vector<double> increment;  // of the difference quotients, per cell
  long jacobian_rhs_evals = 0;
  long jacobian_evals = 0;
  long solves = 0;
  std::size_t nonfinite = SIZE_MAX;  // last component where U or F(U) was not finite
  std::string last_error;
  double t = 0.0;
  long max_steps = 0;  // IntegratorParams::max_steps: the most internal steps of one advance

  Impl(const Rhs& r)
      : rhs(r),
        n(r.size()),
        J(r.nx(), Rhs::stencil_radius),
        P(r.nx(), Rhs::stencil_radius),
        increment(r.nx()) {}
  ~Impl() {
    if (mem) CVodeFree(&mem);
    if (linear_solver) SUNLinSolFree(linear_solver);
    if (opaque_matrix) SUNMatFreeEmpty(opaque_matrix);
    for (N_Vector v : {y, atol, constraints, ftmp, ytmp, ewt, ele})
      if (v) N_VDestroy(v);
    if (ctx) SUNContext_Free(&ctx);
  }

  std::span<double> span_of(N_Vector v) const { return {N_VGetArrayPointer(v), n}; }

  // dU/dt = F(U); a recoverable error (1) when F is not finite, so CVODE retries a smaller step.
  static int rhs_cb(sunrealtype, N_Vector yv, N_Vector fv, void* data) {
    auto* self = static_cast<Impl*>(data);
    self->rhs(self->span_of(yv), self->span_of(fv));
    const double* f = N_VGetArrayPointer(fv);
    const double* y = N_VGetArrayPointer(yv);
    for (std::size_t i = 0; i < self->n; ++i)
      if (!std::isfinite(y[i])) {
        self->nonfinite = i;
        return 1;
      }
    for (std::size_t i = 0; i < self->n; ++i)
      if (!std::isfinite(f[i])) {
        self->nonfinite = i;
        return 1;
      }
    return 0;
  }

  // J by coloured difference quotients about (y, fy) unless CVODE says the saved one will do
  // (jok); then P = I - gamma J, factored (periodic_block_band.hpp). A singular factor is
  // recoverable: CVODE retries with a fresh J or a smaller step. The set-up of both solvers (the
  // preconditioner's of SPGMR, the linear system's of Direct).
  int setup(N_Vector yv, N_Vector fy, sunbooleantype jok, sunbooleantype* jcur, double gamma) {
    if (!jok) {
      if (jacobian(yv, fy) != 0) return 1;
      *jcur = SUNTRUE;
    } else {
      *jcur = SUNFALSE;
    }
    return P.factor_shifted(J, gamma) ? 0 : 1;
  }

  static int psetup(sunrealtype, N_Vector yv, N_Vector fy, sunbooleantype jok, sunbooleantype* jcur,
                    sunrealtype gamma, void* data) {
    return static_cast<Impl*>(data)->setup(yv, fy, jok, jcur, gamma);
  }

  // x = P^{-1} b: the preconditioner solve of SPGMR and the whole solve of Direct.
  void solve(N_Vector b, N_Vector x) {
    N_VScale(1.0, b, x);
    P.solve(span_of(x));
    ++solves;
  }

  static int psolve(sunrealtype, N_Vector, N_Vector, N_Vector r, N_Vector z, sunrealtype,
                    sunrealtype, int, void* data) {
    static_cast<Impl*>(data)->solve(r, z);
    return 0;
  }

  // Direct: CVODE's linear-system function (the matrix it passes is our opaque handle).
  static int linsys(sunrealtype, N_Vector yv, N_Vector fy, SUNMatrix, sunbooleantype jok,
                    sunbooleantype* jcur, sunrealtype gamma, void* data, N_Vector, N_Vector,
                    N_Vector) {
    return static_cast<Impl*>(data)->setup(yv, fy, jok, jcur, gamma);
  }

  // Direct: the SUNLinearSolver's operations. The factorisation is made in linsys, where gamma
  // is known; setup has nothing left to do.
  static SUNLinearSolver_Type direct_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
  static SUNLinearSolver_ID direct_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
  static int direct_setup(SUNLinearSolver, SUNMatrix) { return SUNLS_SUCCESS; }
  static int direct_solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, sunrealtype) {
    static_cast<Impl*>(S->content)->solve(b, x);
    return SUNLS_SUCCESS;
  }
  static int direct_free(SUNLinearSolver S) {
    S->content = nullptr;  // owned by the integrator
    SUNLinSolFreeEmpty(S);
    return SUNLS_SUCCESS;
  }
  static SUNMatrix_ID opaque_id(SUNMatrix) { return SUNMATRIX_CUSTOM; }

  int jacobian(N_Vector yv, N_Vector fy) {
    const std::size_t nx = rhs.nx(), r = Rhs::stencil_radius;
    const double srur = std::sqrt(std::numeric_limits<double>::epsilon());
    CVodeGetErrWeights(mem, ewt);
    const double* yd = N_VGetArrayPointer(yv);
    const double* f0 = N_VGetArrayPointer(fy);
    const double* w = N_VGetArrayPointer(ewt);
    double* yt = N_VGetArrayPointer(ytmp);
    const double* ft = N_VGetArrayPointer(ftmp);
    J.set_zero();
    for (const auto& group : groups) {
      for (std::size_t a = 0; a < 2; ++a) {
        std::copy(yd, yd + n, yt);
        for (std::size_t c : group) {
          const std::size_t i = 2 * c + a;
          increment[c] = srur * std::max(std::fabs(yd[i]), 1.0 / w[i]);
          yt[i] += increment[c];
        }
        if (rhs_cb(t, ytmp, ftmp, this) != 0) return 1;
        ++jacobian_rhs_evals;
        for (std::size_t c : group) {
          for (std::size_t k = 0; k <= 2 * r; ++k) {
            const std::size_t cell = (c + nx + k - r) % nx;
            auto& blk = J.block(cell, c);
            for (std::size_t b = 0; b < 2; ++b)
              blk[2 * b + a] += (ft[2 * cell + b] - f0[2 * cell + b]) / increment[c];
          }
        }
      }
    }
    ++jacobian_evals;
    return 0;
  }

  static void on_error(int, const char* module, const char* function, char* msg, void* data) {
    auto* self = static_cast<Impl*>(data);
    self->last_error = std::string(module) + "/" + function + ": " + msg;
  }
};

namespace {
void check(int flag, const char* what) {
  if (flag != 0) throw std::runtime_error(std::string("CVODE set-up failed in ") + what);
}
}  // namespace

CvodeIntegrator::CvodeIntegrator(const Rhs& rhs, std::span<const double> U0,
                                 const IntegratorParams& p, std::span<const double> abs_scale,
                                 std::span<const double> positive_mask)
    : impl_(std::make_unique<Impl>(rhs)) {
  Impl& m = *impl_;
  const auto N = static_cast<sunindextype>(m.n);
  if (U0.size() != m.n || abs_scale.size() != m.n || positive_mask.size() != m.n)
    throw std::invalid_argument("CvodeIntegrator: vector sizes differ from the right-hand side");
  check(SUNContext_Create(nullptr, &m.ctx), "SUNContext_Create");
  for (N_Vector* v : {&m.y, &m.atol, &m.constraints, &m.ftmp, &m.ytmp, &m.ewt, &m.ele}) {
    *v = N_VNew_Serial(N, m.ctx);
    if (!*v) throw std::runtime_error("CVODE: out of memory");
  }
  std::copy(U0.begin(), U0.end(), N_VGetArrayPointer(m.y));
  auto at = m.span_of(m.atol);
  auto cons = m.span_of(m.constraints);
  for (std::size_t i = 0; i < m.n; ++i) {
    at[i] = p.atol * abs_scale[i];
    cons[i] = positive_mask[i] != 0.0 ? 2.0 : 0.0;  // 2: strictly positive
  }
  m.mem = CVodeCreate(CV_BDF, m.ctx);
  if (!m.mem) throw std::runtime_error("CVODE: CVodeCreate failed");
  check(CVodeSetErrHandlerFn(m.mem, &Impl::on_error, &m), "CVodeSetErrHandlerFn");
  check(CVodeInit(m.mem, &Impl::rhs_cb, 0.0, m.y), "CVodeInit");
  check(CVodeSVtolerances(m.mem, p.rtol, m.atol), "CVodeSVtolerances");
  check(CVodeSetUserData(m.mem, &m), "CVodeSetUserData");
  m.max_steps = p.max_steps;
  if (p.steps_per_call < 1) throw std::invalid_argument("CvodeIntegrator: steps_per_call < 1");
  check(CVodeSetMaxNumSteps(m.mem, std::min(p.max_steps, p.steps_per_call)), "CVodeSetMaxNumSteps");
  check(CVodeSetMaxOrd(m.mem, p.max_order), "CVodeSetMaxOrd");
  check(CVodeSetConstraints(m.mem, m.constraints), "CVodeSetConstraints");

  m.groups = colour_cells(rhs.nx(), Rhs::stencil_radius);
  if (p.linear_solver == LinearSolver::Direct) {
    m.opaque_matrix = SUNMatNewEmpty(m.ctx);
    m.linear_solver = SUNLinSolNewEmpty(m.ctx);
    if (!m.opaque_matrix || !m.linear_solver) throw std::runtime_error("CVODE: out of memory");
    m.opaque_matrix->ops->getid = &Impl::opaque_id;
    m.linear_solver->content = &m;
    m.linear_solver->ops->gettype = &Impl::direct_type;
    m.linear_solver->ops->getid = &Impl::direct_id;
    m.linear_solver->ops->setup = &Impl::direct_setup;
    m.linear_solver->ops->solve = &Impl::direct_solve;
    m.linear_solver->ops->free = &Impl::direct_free;
    check(CVodeSetLinearSolver(m.mem, m.linear_solver, m.opaque_matrix), "CVodeSetLinearSolver");
    check(CVodeSetLinSysFn(m.mem, &Impl::linsys), "CVodeSetLinSysFn");
  } else {
    const bool band = p.linear_solver == LinearSolver::KrylovBand;
    m.linear_solver = SUNLinSol_SPGMR(m.y, band ? SUN_PREC_LEFT : SUN_PREC_NONE, 10, m.ctx);
    if (!m.linear_solver) throw std::runtime_error("CVODE: SUNLinSol_SPGMR failed");
    check(CVodeSetLinearSolver(m.mem, m.linear_solver, nullptr), "CVodeSetLinearSolver");
    check(CVodeSetEpsLin(m.mem, p.eps_lin), "CVodeSetEpsLin");
    if (band)
      check(CVodeSetPreconditioner(m.mem, &Impl::psetup, &Impl::psolve), "CVodeSetPreconditioner");
  }
}

CvodeIntegrator::~CvodeIntegrator() = default;

AdvanceResult CvodeIntegrator::advance_to(double t_out, const AdvanceLimits& limits) {
  Impl& m = *impl_;
  AdvanceResult res;
  sunrealtype t_reached = m.t;
  long steps_before = 0, steps_now = 0;
  CVodeGetNumSteps(m.mem, &steps_before);
  int flag = CV_SUCCESS;
  for (;;) {
    flag = CVode(m.mem, t_out, m.y, &t_reached, CV_NORMAL);
    CVodeGetNumSteps(m.mem, &steps_now);
    res.steps = steps_now - steps_before;
    if (flag != CV_TOO_MUCH_WORK) break;  // (a chunk's end: CVODE continues on the next call)
    if (limits.stop && limits.stop->load()) {
      res.interrupted = true;
      break;
    }
    if (limits.stall_steps > 0 && res.steps >= limits.stall_steps) {
      res.stalled = true;
      break;
    }
    if (res.steps >= m.max_steps) break;
  }
  m.t = t_reached;
  res.t = t_reached;
  sunrealtype last_step = 0.0;
  if (CVodeGetLastStep(m.mem, &last_step) == CV_SUCCESS) res.last_step = last_step;
  if (res.interrupted) return res;
  if (flag < 0) {
    res.ok = false;
    if (flag == CV_TOO_MUCH_WORK)
      res.message = "CVODE took " + std::to_string(res.steps) +
                    " steps without reaching t = " + std::to_string(t_out) + " s";
    else
      res.message =
          m.last_error.empty() ? "CVODE failed with flag " + std::to_string(flag) : m.last_error;
    if (m.nonfinite != SIZE_MAX) {
      res.worst = m.nonfinite;
      res.nonfinite = true;
    } else if (CVodeGetErrWeights(m.mem, m.ewt) == 0 && CVodeGetEstLocalErrors(m.mem, m.ele) == 0) {
      const double* e = N_VGetArrayPointer(m.ele);
      const double* w = N_VGetArrayPointer(m.ewt);
      double worst = -1.0;
      for (std::size_t i = 0; i < m.n; ++i)
        if (std::fabs(e[i] * w[i]) > worst) {
          worst = std::fabs(e[i] * w[i]);
          res.worst = i;
        }
    }
  }
  return res;
}

std::span<const double> CvodeIntegrator::state() const {
  return impl_->span_of(impl_->y);
}
double CvodeIntegrator::time() const {
  return impl_->t;
}

CvodeStats CvodeIntegrator::stats() const {
  const Impl& m = *impl_;
  CvodeStats s;
  CVodeGetNumSteps(m.mem, &s.steps);
  CVodeGetNumRhsEvals(m.mem, &s.rhs_evals);
  CVodeGetNumLinRhsEvals(m.mem, &s.rhs_evals_jtimes);
  s.rhs_evals_jacobian = m.jacobian_rhs_evals;
  s.jacobian_evals = m.jacobian_evals;
  s.linear_solves = m.solves;
  CVodeGetNumLinIters(m.mem, &s.linear_iterations);
  CVodeGetNumNonlinSolvIters(m.mem, &s.nonlinear_iterations);
  CVodeGetNumErrTestFails(m.mem, &s.error_test_failures);
  CVodeGetNumNonlinSolvConvFails(m.mem, &s.nonlinear_convergence_failures);
  CVodeGetLastOrder(m.mem, &s.last_order);
  sunrealtype h = 0.0;
  CVodeGetLastStep(m.mem, &h);
  s.last_step = h;
  return s;
}

}  // namespace granbench::depthavg

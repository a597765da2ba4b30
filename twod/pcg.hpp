// Preconditioned conjugate gradients for symmetric positive-definite systems, written once for
// every operator/preconditioner pair of the solver (matrix-free or Eigen sparse).
//
//   r0 = b - A x0, z = M^{-1} r, d = z;  repeat: alpha = (r.z)/(d.Ad), x += alpha d,
//   r -= alpha A d, stop when ||r|| <= tol ||b||; beta = (r.z)_new/(r.z)_old, d = z + beta d.
//
// The dot products and norms are the fixed-block sums of parallel.hpp, so the iterates - and the
// iteration counts - do not depend on the number of threads; the vector updates are parallel.
#pragma once

#include <Eigen/Dense>
#include <cmath>

#include "twod/parallel.hpp"

namespace granbench::twod {

// The iteration's vectors, kept by the caller from one solve to the next: allocating them per
// solve (several 100 kB per step) made the kernel zero fresh pages on every step, 12 % of a
// one-thread 2D run and serial (docs/performance.md).
struct PcgWorkspace {
  Eigen::VectorXd r, z, q, d;
};

// Returns the iterations used, or -1 if max_iterations did not reach the tolerance.
// apply(x, y): y = A x;  precondition(r, z): z = M^{-1} r.
template <class Apply, class Precondition>
int pcg(Apply&& apply, Precondition&& precondition, const Eigen::VectorXd& b, Eigen::VectorXd& x,
        double tol, int max_iterations, PcgWorkspace& work) {
  const double bnorm = std::sqrt(deterministic_dot(b, b));
  if (bnorm == 0.0) {
    x.setZero(b.size());
    return 0;
  }
  Eigen::VectorXd &r = work.r, &z = work.z, &q = work.q, &d = work.d;
  r.resize(b.size());
  z.resize(b.size());
  q.resize(b.size());
  apply(x, q);
  parallel_difference(b, q, r);
  const double target = tol * bnorm;
  if (std::sqrt(deterministic_dot(r, r)) <= target) return 0;
  precondition(r, z);
  parallel_copy(z, d);
  double rz = deterministic_dot(r, z);
  for (int it = 1; it <= max_iterations; ++it) {
    apply(d, q);
    const double alpha = rz / deterministic_dot(d, q);
    const double rr = cg_update(alpha, d, q, x, r);  // x += alpha d, r -= alpha q; r . r
    if (std::sqrt(rr) <= target) return it;
    precondition(r, z);
    const double rz_new = deterministic_dot(r, z);
    cg_direction(z, rz_new / rz, d);  // d = z + beta d
    rz = rz_new;
  }
  return -1;
}

}  // namespace granbench::twod

// Preconditioned conjugate gradients for symmetric positive-definite systems, written once for
// every operator/preconditioner pair of the solver (matrix-free or Eigen sparse).
//
//   r0 = b - A x0, z = M^{-1} r, d = z;  repeat: alpha = (r.z)/(d.Ad), x += alpha d,
//   r -= alpha A d, stop when ||r|| <= tol ||b||; beta = (r.z)_new/(r.z)_old, d = z + beta d.
#pragma once

#include <Eigen/Dense>

namespace granbench::twod {

// Returns the iterations used, or -1 if max_iterations did not reach the tolerance.
// apply(x, y): y = A x;  precondition(r, z): z = M^{-1} r.
template <class Apply, class Precondition>
int pcg(Apply&& apply, Precondition&& precondition, const Eigen::VectorXd& b, Eigen::VectorXd& x,
        double tol, int max_iterations) {
  const double bnorm = b.norm();
  if (bnorm == 0.0) {
    x.setZero(b.size());
    return 0;
  }
  Eigen::VectorXd r(b.size()), z(b.size()), q(b.size());
  apply(x, q);
  r = b - q;
  const double target = tol * bnorm;
  if (r.norm() <= target) return 0;
  precondition(r, z);
  Eigen::VectorXd d = z;
  double rz = r.dot(z);
  for (int it = 1; it <= max_iterations; ++it) {
    apply(d, q);
    const double alpha = rz / d.dot(q);
    x.noalias() += alpha * d;
    r.noalias() -= alpha * q;
    if (r.norm() <= target) return it;
    precondition(r, z);
    const double rz_new = r.dot(z);
    d = z + (rz_new / rz) * d;
    rz = rz_new;
  }
  return -1;
}

}  // namespace granbench::twod

// GSL Brent iteration behind brent_root; see root_finding.hpp.
#include "common/root_finding.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <memory>
#include <stdexcept>

namespace granbench {

double brent_root(const std::function<double(double)>& f, double lo, double hi, double tol) {
  gsl_function fn;
  fn.function = [](double x, void* p) {
    return (*static_cast<const std::function<double(double)>*>(p))(x);
  };
  fn.params = const_cast<std::function<double(double)>*>(&f);
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  // GSL's default handler aborts; report a bad bracket as an exception instead.
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  const int status = gsl_root_fsolver_set(solver.get(), &fn, lo, hi);
  if (status != GSL_SUCCESS) {
    gsl_set_error_handler(old);
    throw std::invalid_argument("brent_root: the interval does not bracket a root");
  }
  double x = 0.5 * (lo + hi);
  for (int iter = 0; iter < 300; ++iter) {
    gsl_root_fsolver_iterate(solver.get());
    x = gsl_root_fsolver_root(solver.get());
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()),
                               gsl_root_fsolver_x_upper(solver.get()), tol, 0.0) == GSL_SUCCESS)
      break;
  }
  gsl_set_error_handler(old);
  return x;
}

}  // namespace granbench

// Bracketed scalar root finding with GSL's Brent solver, shared by the curve inverses, the
// neutral points of C(I) and the dispersion cutoff.
#pragma once

#include <functional>

namespace granbench {

// Root of f on [lo, hi] (f(lo), f(hi) of opposite sign), to an absolute interval width tol.
double brent_root(const std::function<double(double)>& f, double lo, double hi, double tol = 1e-13);

}  // namespace granbench

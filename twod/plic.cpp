// PLIC line-area geometry in the unit square (Scardovelli & Zaleski 2000): the area cut by
// m1 X + m2 Z <= alpha, its inverse, and the fraction in a sub-rectangle (used for the fluxes
// of the directionally split advection, vof_advection.cpp).
//
// After reflecting to m1, m2 >= 0 and normalising m1 + m2 = 1 with a = min, b = max:
//   area = alpha^2/(2ab)               alpha <  a
//        = (alpha - a/2)/b             a <= alpha <= b
//        = 1 - (1 - alpha)^2/(2ab)     alpha >  b
// and the inverse follows branch by branch with c1 = a/(2b).
#include "twod/plic.hpp"

#include <algorithm>
#include <cmath>

namespace granbench::twod {

namespace {
struct Normalised {
  double a, b, alpha, scale;
};
// Reflect to non-negative components and normalise to m1 + m2 = 1.
Normalised normalise(double m1, double m2, double alpha) {
  if (m1 < 0.0) {
    alpha -= m1;
    m1 = -m1;
  }
  if (m2 < 0.0) {
    alpha -= m2;
    m2 = -m2;
  }
  const double s = m1 + m2;
  return {std::min(m1, m2) / s, std::max(m1, m2) / s, alpha / s, s};
}
}  // namespace

double plic_area(double m1, double m2, double alpha) {
  if (m1 == 0.0 && m2 == 0.0) return alpha >= 0.0 ? 1.0 : 0.0;
  const auto n = normalise(m1, m2, alpha);
  if (n.alpha <= 0.0) return 0.0;
  if (n.alpha >= 1.0) return 1.0;
  if (n.alpha < n.a) return n.alpha * n.alpha / (2.0 * n.a * n.b);
  if (n.alpha <= n.b) return (n.alpha - 0.5 * n.a) / n.b;
  const double r = 1.0 - n.alpha;
  return 1.0 - r * r / (2.0 * n.a * n.b);
}

double plic_alpha(double m1, double m2, double c) {
  const double s = std::abs(m1) + std::abs(m2);
  const double shift = std::min(m1, 0.0) + std::min(m2, 0.0);  // undo the reflection
  const double a = std::min(std::abs(m1), std::abs(m2)) / s;
  const double b = std::max(std::abs(m1), std::abs(m2)) / s;
  c = std::clamp(c, 0.0, 1.0);
  const double c1 = 0.5 * a / b;
  double alpha;
  if (c <= c1)
    alpha = std::sqrt(2.0 * a * b * c);
  else if (c <= 1.0 - c1)
    alpha = c * b + 0.5 * a;
  else
    alpha = 1.0 - std::sqrt(2.0 * a * b * (1.0 - c));
  return alpha * s + shift;
}

double plic_rect_fraction(double m1, double m2, double alpha, double x0, double wx, double z0,
                          double wz) {
  // In sub-rectangle coordinates X' = (X - x0)/wx, Z' = (Z - z0)/wz the line reads
  // (m1 wx) X' + (m2 wz) Z' = alpha - m1 x0 - m2 z0.
  return plic_area(m1 * wx, m2 * wz, alpha - m1 * x0 - m2 * z0);
}

}  // namespace granbench::twod

// Spectral convergence of the 2D linear stability eigenvalue in the number of Chebyshev
// intervals N, with the map z = h0 (1 - s^2) that makes the eigenfunctions smooth functions of
// s = sqrt(1 - z/h0); and what the plain map z = h0 (1 - s) does instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "analysis/linear2d/linear_stability_2d.hpp"
#include "tests/support/verification_table.hpp"

using namespace granbench;
using namespace granbench::linear2d;
namespace vt = granbench::testing;

namespace {
LinearBaseState section7() {
  const MuCurve c(CurveKind::Regularised, Material{}, 4e-3);
  return mu_i_base_state(steady_state(c, degrees_to_radians(28.5), 4e-3), c);
}
constexpr double k_hat_8cm = 2.0 * 3.14159265358979323846 * 4e-3 / 0.08;

// The eigenvalue at N nearest to the reference surface mode.
std::complex<double> nearest(const LinearBaseState& b, int N, VerticalMap map,
                             std::complex<double> ref) {
  const auto sp = spectrum(b, k_hat_8cm, N, map);
  return *std::min_element(sp.begin(), sp.end(),
                           [&](auto x, auto y) { return std::abs(x - ref) < std::abs(y - ref); });
}
}  // namespace

TEST(Linear2DConvergence, SquareRootMapConvergesSpectrally) {
  const LinearBaseState b = section7();
  const auto ref = surface_mode_eigenvalue(b, k_hat_8cm, 48);
  const std::vector<int> Ns{8, 12, 16, 20, 24};
  std::vector<double> err;
  for (int N : Ns)
    err.push_back(std::abs(nearest(b, N, VerticalMap::SquareRoot, ref) - ref) / std::abs(ref));
  vt::VerificationTable table(
      "linear2d_sqrt_map", "Exact 2D linear stability: Chebyshev intervals, square-root map",
      "Surface-mode eigenvalue at Lx = 8 cm (28.5 deg, h0 = 4 mm, regularised curve), map z = h0 "
      "(1 - s^2), relative error against N = 48.",
      {"N", "relative error", "local order log(e1/e2)/log(N2/N1)"});
  table.bound(
      "each local order exceeds the previous one by more than 1 (spectral: faster than "
      "any power)");
  table.bound("the last local order > 10, the error at N = 24 < 1e-6");
  // Spectral (faster than any power): the local algebraic order keeps rising.
  double previous_order = 0.0;
  for (std::size_t i = 0; i < err.size(); ++i) {
    if (i == 0) {
      table.row({std::to_string(Ns[i]), vt::sci(err[i]), vt::dash()});
      continue;
    }
    const double order = std::log(err[i - 1] / err[i]) / std::log(double(Ns[i]) / Ns[i - 1]);
    table.row({std::to_string(Ns[i]), vt::sci(err[i]), vt::fixed(order)});
    EXPECT_GT(order, previous_order + 1.0) << i;
    previous_order = order;
  }
  EXPECT_GT(previous_order, 10.0);
  EXPECT_LT(err.back(), 1e-6);
  table.write();
}

TEST(Linear2DConvergence, LinearMapConvergesToAWrongEigenvalue) {
  // With z = h0 (1 - s) the constitutive row at the surface loses its du/dz term (eta_s -> 0)
  // and imposes tau_xz = q p there, which with the stress conditions tau_xz = mu h, p = h forces
  // q = mu: the surface mode is not represented, and the eigenvalue nearest to it stays ~30% away
  // (with a negative growth rate) however many points are used.
  const LinearBaseState b = section7();
  const auto ref = surface_mode_eigenvalue(b, k_hat_8cm, 48);
  const auto sq = std::abs(nearest(b, 12, VerticalMap::SquareRoot, ref) - ref) / std::abs(ref);
  std::vector<double> err;
  vt::VerificationTable table(
      "linear2d_linear_map", "Exact 2D linear stability: the plain map fails",
      "The same eigenvalue with the map z = h0 (1 - s): the surface mode is not represented, and "
      "the nearest eigenvalue stays far from it however many intervals are used.",
      {"N", "relative error", "Re(lambda_hat)"});
  table.bound("error > 0.1 and > 1e3 x the square-root map's error at N = 12 (" + vt::sci(sq) +
              ") on every grid");
  table.bound("observed order between N = 24 and 48 < 1");
  for (int N : {12, 24, 48}) {
    const auto l = nearest(b, N, VerticalMap::Linear, ref);
    err.push_back(std::abs(l - ref) / std::abs(ref));
    table.row({std::to_string(N), vt::sci(err.back()), vt::sci(l.real())});
    EXPECT_GT(err.back(), 0.1);
    EXPECT_GT(err.back(), 1e3 * sq);  // far worse than the square-root map at N = 12
  }
  const double order = std::log2(err[1] / err[2]);
  table.row({"order 24 -> 48", vt::fixed(order), vt::dash()});
  EXPECT_LT(order, 1.0);
  table.write();
}

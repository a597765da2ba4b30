// The Newton matrix's solver (depthavg/periodic_block_band.hpp): on random periodic block-band
// matrices A = I - gamma J, its solve must be A's exact inverse to round-off, wrap-around blocks
// included, for stencil radii 1-3 and for grids from the smallest allowed (2r + 1 cells) up.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "depthavg/periodic_block_band.hpp"
#include "tests/support/random_vector.hpp"

namespace granbench {
namespace {

// J with standard-normal entries in every block at cyclic distance <= radius; also as a dense
// matrix, the periodic wrap-around in the corners.
struct RandomJacobian {
  depthavg::PeriodicBlockBandMatrix J;
  Eigen::MatrixXd dense;
  RandomJacobian(std::size_t cells, std::size_t radius, unsigned seed)
      : J(cells, radius), dense(Eigen::MatrixXd::Zero(2 * cells, 2 * cells)) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    J.set_zero();
    for (std::size_t i = 0; i < cells; ++i)
      for (std::size_t k = 0; k <= 2 * radius; ++k) {
        const std::size_t j = (i + cells + k - radius) % cells;
        auto& blk = J.block(i, j);
        for (int e = 0; e < 4; ++e) {
          blk[e] = normal(rng);
          dense(static_cast<Eigen::Index>(2 * i + e / 2),
                static_cast<Eigen::Index>(2 * j + e % 2)) = blk[e];
        }
      }
  }
};

TEST(PeriodicBlockBand, SolveIsTheExactInverseOfIMinusGammaJ) {
  struct Case {
    std::size_t cells, radius;
  };
  for (const Case c :
       {Case{5, 2}, Case{6, 2}, Case{32, 2}, Case{3, 1}, Case{17, 1}, Case{7, 3}, Case{40, 3}}) {
    const RandomJacobian rj(c.cells, c.radius, static_cast<unsigned>(7 * c.cells + c.radius));
    const double gamma = 0.05;
    depthavg::PeriodicBlockBandMatrix P(c.cells, c.radius);
    ASSERT_TRUE(P.factor_shifted(rj.J, gamma)) << c.cells << " cells, radius " << c.radius;
    const auto n = static_cast<int>(2 * c.cells);
    const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n, n) - gamma * rj.dense;
    const Eigen::VectorXd b = testing::random_vector(n, 11);
    std::vector<double> x(b.data(), b.data() + n);
    P.solve(x);
    const Eigen::VectorXd residual = A * Eigen::Map<const Eigen::VectorXd>(x.data(), n) - b;
    EXPECT_LT(residual.norm(), 1e-13 * b.norm()) << c.cells << " cells, radius " << c.radius;
    // and it is not the band part's inverse: the wrap-around blocks change the answer
    const Eigen::VectorXd exact = A.partialPivLu().solve(b);
    EXPECT_LT((Eigen::Map<const Eigen::VectorXd>(x.data(), n) - exact).norm(),
              1e-12 * exact.norm());
  }
}

TEST(PeriodicBlockBand, ASingularMatrixIsReported) {
  // gamma J = I everywhere: A = 0, every pivot block singular.
  depthavg::PeriodicBlockBandMatrix J(8, 2), P(8, 2);
  J.set_zero();
  for (std::size_t i = 0; i < 8; ++i) J.block(i, i) = {1.0, 0.0, 0.0, 1.0};
  EXPECT_FALSE(P.factor_shifted(J, 1.0));
  EXPECT_TRUE(P.factor_shifted(J, 0.5));
}

TEST(PeriodicBlockBand, FewerCellsThanTheStencilIsRefused) {
  EXPECT_THROW(depthavg::PeriodicBlockBandMatrix(4, 2), std::invalid_argument);
}

}  // namespace
}  // namespace granbench

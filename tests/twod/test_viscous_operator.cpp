// The matrix-free viscous operator (twod/viscous_operator.cpp) against its own assembled matrix
// and against the properties it must have: symmetric positive definite (the stress work is a
// sum of squares), a symmetric preconditioner (conjugate gradients needs one), and the stress
// of a rigid motion is zero (only the mass term acts on a uniform translation).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tests/support/random_vector.hpp"
#include "twod/viscous_operator.hpp"

using namespace granbench::twod;
using granbench::testing::random_vector;

namespace {
// Properties with rough, strongly varying viscosities (a contrast of 1e6, as at a free surface)
// on an anisotropic grid.
Properties rough_properties(const Grid& g, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Properties p(g);
  for (auto& v : p.rho_u) v = 1.5 + 1500.0 * unit(rng);
  for (auto& v : p.rho_w) v = 1.5 + 1500.0 * unit(rng);
  for (auto& v : p.eta_c) v = std::pow(10.0, -3.0 + 6.0 * unit(rng));
  for (auto& v : p.eta_n) v = std::pow(10.0, -3.0 + 6.0 * unit(rng));
  return p;
}

}  // namespace

TEST(ViscousOperator, ProductEqualsTheAssembledMatrixWhichIsSymmetric) {
  const Grid g(7, 5, 0.07, 0.01);
  ViscousOperator op(g);
  op.set(rough_properties(g, 1), 1e-4);
  PatternedMatrix A;
  op.assemble(A);
  const Eigen::VectorXd x = random_vector(op.size(), 2);
  Eigen::VectorXd y;
  op.apply(x, y);
  const Eigen::VectorXd Ax = A.matrix() * x;
  EXPECT_LT((y - Ax).norm(), 1e-13 * Ax.norm());
  const Eigen::SparseMatrix<double> At = A.matrix().transpose();
  const Eigen::SparseMatrix<double> Acol = A.matrix();
  EXPECT_LT((Acol - At).norm(), 1e-13 * Acol.norm());
  // Positive definite: a Cholesky factorisation exists.
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt(Acol);
  EXPECT_EQ(llt.info(), Eigen::Success);
}

TEST(ViscousOperator, LineRelaxationIsASymmetricPositivePreconditioner) {
  // The sweep goes over blocks of 8 columns in two colours: one block (8 columns), an odd
  // number of blocks whose last one neighbours the first across the periodic boundary (24, 3
  // blocks), an even number (64, 8 blocks), and a last block that is short (37, 5 blocks).
  for (int nx : {8, 24, 37, 64}) {
    SCOPED_TRACE(nx);
    const Grid g(nx, 6, 0.01 * nx, 0.008);
    ViscousOperator op(g);
    op.set(rough_properties(g, 3), 1e-4);
    const Eigen::VectorXd r1 = random_vector(op.size(), 4), r2 = random_vector(op.size(), 5);
    Eigen::VectorXd z1, z2;
    op.precondition(r1, z1);
    op.precondition(r2, z2);
    EXPECT_NEAR(r1.dot(z2), r2.dot(z1), 1e-12 * std::abs(r1.dot(z2)) + 1e-300);
    EXPECT_GT(r1.dot(z1), 0.0);
    EXPECT_GT(r2.dot(z2), 0.0);
  }
}

TEST(ViscousOperator, PreconditionerIsTheSymmetricLineGaussSeidelSweepOfTheAssembledMatrix) {
  // The reference: z = 0, then each line solved exactly against the assembled matrix with the
  // latest z of the other lines, in the documented order (u-lines, then w-lines; within each,
  // the even blocks of 8 columns, then the odd ones, blocks and columns ascending), then the
  // whole sequence reversed. The operator's written-out right-hand sides, its four lines solved
  // at once and its threads must give the same z.
  for (int nx : {8, 24, 37, 64}) {
    SCOPED_TRACE(nx);
    const int nz = 6, chunk = 8;
    const Grid g(nx, nz, 0.01 * nx, 0.008);
    ViscousOperator op(g);
    op.set(rough_properties(g, 6), 1e-4);
    PatternedMatrix assembled;
    op.assemble(assembled);
    const Eigen::MatrixXd A(assembled.matrix());
    const Eigen::VectorXd r = random_vector(op.size(), 7);
    std::vector<std::vector<int>> lines;  // the forward order
    const int blocks = (nx + chunk - 1) / chunk;
    for (bool u_lines : {true, false})
      for (int colour : {0, 1})
        for (int b = colour; b < blocks; b += 2)
          for (int i = b * chunk; i < std::min(nx, (b + 1) * chunk); ++i) {
            std::vector<int> rows;
            if (u_lines)
              for (int k = 0; k < nz; ++k) rows.push_back(op.u_index(i, k));
            else
              for (int k = 1; k < nz; ++k) rows.push_back(op.w_index(i, k));
            lines.push_back(rows);
          }
    std::vector<std::vector<int>> sequence = lines;
    sequence.insert(sequence.end(), lines.rbegin(), lines.rend());
    Eigen::VectorXd reference = Eigen::VectorXd::Zero(op.size());
    for (const std::vector<int>& rows : sequence) {
      const int m = int(rows.size());
      Eigen::MatrixXd block(m, m);
      Eigen::VectorXd rhs(m);
      for (int a = 0; a < m; ++a) {
        rhs[a] = r[rows[a]] - A.row(rows[a]).dot(reference);
        for (int b = 0; b < m; ++b) {
          block(a, b) = A(rows[a], rows[b]);
          rhs[a] += A(rows[a], rows[b]) * reference[rows[b]];  // the line's own part back
        }
      }
      const Eigen::VectorXd solution = block.partialPivLu().solve(rhs);
      for (int a = 0; a < m; ++a) reference[rows[a]] = solution[a];
    }
    Eigen::VectorXd z;
    op.precondition(r, z);
    EXPECT_LT((z - reference).norm(), 1e-10 * reference.norm());
  }
}

TEST(ViscousOperator, RigidTranslationFeelsOnlyTheMassAwayFromTheBed) {
  // u = 1, w = 0 everywhere: D = 0 except at the no-slip bed corners, so A x = (rho V/dt) x in
  // every row but the bottom u-row.
  const Grid g(6, 4, 0.06, 0.004);
  const double dt = 1e-3;
  const Properties props = rough_properties(g, 6);
  ViscousOperator op(g);
  op.set(props, dt);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(op.size()), y;
  for (int i = 0; i < g.nx; ++i)
    for (int k = 0; k < g.nz; ++k) x[op.u_index(i, k)] = 1.0;
  op.apply(x, y);
  const double V = g.cell_volume();
  for (int i = 0; i < g.nx; ++i) {
    for (int k = 1; k < g.nz; ++k) {
      EXPECT_NEAR(y[op.u_index(i, k)], props.rho_u[g.at(i, k)] * V / dt,
                  1e-12 * props.rho_u[g.at(i, k)] * V / dt);
      EXPECT_NEAR(y[op.w_index(i, k)], 0.0, 1e-9 * props.eta_n[g.at(i, k)] * V / (g.dx * g.dz));
    }
    // The bed: the shear stress of the slip against the wall, 2 eta V / dz^2 (gamma = 2u/dz on
    // half a volume).
    const double bed =
        props.rho_u[g.at(i, 0)] * V / dt + 2.0 * props.eta_n[g.at(i, 0)] * V / (g.dz * g.dz);
    EXPECT_NEAR(y[op.u_index(i, 0)], bed, 1e-12 * bed);
  }
}

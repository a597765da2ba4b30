// Test support: a reproducible vector of standard-normal entries, for the tests of the linear
// operators and preconditioners of twod/ (header only; include by path from the source root).
#pragma once

#include <Eigen/Dense>
#include <random>

namespace granbench::testing {

inline Eigen::VectorXd random_vector(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = normal(rng);
  return v;
}

}  // namespace granbench::testing

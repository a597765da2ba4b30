// Thread count and fixed-partition sums of the 2D solver; see parallel.hpp.
#include "twod/parallel.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace granbench::twod {

int thread_count() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

void set_thread_count(int n) {
  if (n < 1) throw std::invalid_argument("set_thread_count: need n >= 1");
#ifdef _OPENMP
  omp_set_num_threads(n);
#endif
}

void parallel_for(int n, bool parallel, IndexBody body) {
  if (parallel && n > 1 && thread_count() > 1) {
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; ++i) body(i);
  } else {
    for (int i = 0; i < n; ++i) body(i);
  }
}

namespace {

// sum over the blocks b of block_sum(lo_b, hi_b), added in block order; blocks in parallel.
template <class BlockSum>
double blocked_sum(Eigen::Index n, BlockSum&& block_sum) {
  const Eigen::Index nb = (n + kBlock - 1) / kBlock;
  double small[64];
  std::vector<double> large;
  double* parts = small;
  if (nb > 64) {
    large.resize(nb);
    parts = large.data();
  }
  parallel_for(int(nb), true, [&](int b) {
    const Eigen::Index lo = b * kBlock;
    parts[b] = block_sum(lo, std::min(n, lo + kBlock) - lo);
  });
  double sum = 0.0;
  for (Eigen::Index b = 0; b < nb; ++b) sum += parts[b];
  return sum;
}

}  // namespace

double deterministic_dot(const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  return blocked_sum(x.size(), [&](Eigen::Index lo, Eigen::Index len) {
    return x.segment(lo, len).dot(y.segment(lo, len));
  });
}

double cg_update(double alpha, const Eigen::VectorXd& d, const Eigen::VectorXd& q,
                 Eigen::VectorXd& x, Eigen::VectorXd& r) {
  return blocked_sum(x.size(), [&](Eigen::Index lo, Eigen::Index len) {
    x.segment(lo, len).noalias() += alpha * d.segment(lo, len);
    r.segment(lo, len).noalias() -= alpha * q.segment(lo, len);
    return r.segment(lo, len).squaredNorm();
  });
}

namespace {

// block(lo, len) for the fixed blocks of [0, n), in parallel.
template <class Block>
void for_blocks(Eigen::Index n, Block&& block) {
  const Eigen::Index nb = (n + kBlock - 1) / kBlock;
  parallel_for(int(nb), true, [&](int b) {
    const Eigen::Index lo = b * kBlock;
    block(lo, std::min(n, lo + kBlock) - lo);
  });
}

}  // namespace

void cg_direction(const Eigen::VectorXd& z, double beta, Eigen::VectorXd& d) {
  for_blocks(z.size(), [&](Eigen::Index lo, Eigen::Index len) {
    d.segment(lo, len) = z.segment(lo, len) + beta * d.segment(lo, len);
  });
}

void parallel_copy(const Eigen::VectorXd& from, Eigen::VectorXd& to) {
  to.resize(from.size());
  for_blocks(from.size(), [&](Eigen::Index lo, Eigen::Index len) {
    to.segment(lo, len) = from.segment(lo, len);
  });
}

void parallel_zero(Eigen::Index n, Eigen::VectorXd& x) {
  x.resize(n);
  for_blocks(n, [&](Eigen::Index lo, Eigen::Index len) { x.segment(lo, len).setZero(); });
}

void parallel_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b, Eigen::VectorXd& out) {
  out.resize(a.size());
  for_blocks(a.size(), [&](Eigen::Index lo, Eigen::Index len) {
    out.segment(lo, len) = a.segment(lo, len) - b.segment(lo, len);
  });
}

}  // namespace granbench::twod

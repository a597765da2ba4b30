// Thread count and fixed-partition sums of the 2D solver; see parallel.hpp.
#include "twod/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "twod/thread_team.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace granbench::twod {

namespace {
#ifndef _OPENMP
thread_local int serial_build_thread_count = 1;
#endif

// The calling thread's team, remade when the thread count changes.
ThreadTeam& team_of_this_thread(int threads) {
  thread_local std::unique_ptr<ThreadTeam> team;
  if (!team || team->size() != threads) {
    team.reset();  // (join the old workers before starting new ones)
    team = std::make_unique<ThreadTeam>(threads);
  }
  return *team;
}
}  // namespace

int thread_count() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return serial_build_thread_count;
#endif
}

void set_thread_count(int n) {
  if (n < 1) throw std::invalid_argument("set_thread_count: need n >= 1");
#ifdef _OPENMP
  omp_set_num_threads(n);
#else
  serial_build_thread_count = n;
#endif
}

void parallel_for(int n, bool parallel, IndexBody body) {
  const int threads = parallel ? thread_count() : 1;
  if (threads > 1 && n > 1 && !ThreadTeam::inside_a_loop())
    team_of_this_thread(threads).run(n, body, body.identity());
  else
    for (int i = 0; i < n; ++i) body(i);
}

void parallel_for_ranges(int n, RangeBody body) {
  const int threads = thread_count();
  if (threads == 1 || n <= 1 || ThreadTeam::inside_a_loop()) {
    body(0, n);
    return;
  }
  team_of_this_thread(threads).run_ranges(n, body, body.identity());
}

namespace {

// combine(...combine(value(block 0), value(block 1))..., value(block nb-1)) over the fixed blocks
// of [0, n), in block order; the blocks' values are computed in parallel.
template <class BlockValue, class Combine>
double blocked_reduce(Eigen::Index n, BlockValue&& block_value, Combine&& combine) {
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
    parts[b] = block_value(lo, std::min(n, lo + kBlock) - lo);
  });
  double result = 0.0;
  for (Eigen::Index b = 0; b < nb; ++b) result = combine(result, parts[b]);
  return result;
}

template <class BlockSum>
double blocked_sum(Eigen::Index n, BlockSum&& block_sum) {
  return blocked_reduce(n, block_sum, [](double a, double b) { return a + b; });
}

}  // namespace

double parallel_max_abs(const std::vector<double>& v) {
  return blocked_reduce(
      Eigen::Index(v.size()),
      [&](Eigen::Index lo, Eigen::Index len) {
        double m = 0.0;
        for (Eigen::Index j = lo; j < lo + len; ++j) m = std::max(m, std::abs(v[j]));
        return m;
      },
      [](double a, double b) { return std::max(a, b); });
}

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

// Element-wise vector operations: one contiguous share per thread (parallel_for_ranges), the
// inner loop vectorised (the fixed blocks matter for sums only).
template <class Segment>
void for_segments(Eigen::Index n, Segment&& segment) {
  parallel_for_ranges(int(n), [&](int begin, int end) { segment(begin, end - begin); });
}

}  // namespace

void cg_direction(const Eigen::VectorXd& z, double beta, Eigen::VectorXd& d) {
  for_segments(z.size(), [&](Eigen::Index lo, Eigen::Index len) {
    d.segment(lo, len) = z.segment(lo, len) + beta * d.segment(lo, len);
  });
}

void parallel_copy(const Eigen::VectorXd& from, Eigen::VectorXd& to) {
  to.resize(from.size());
  for_segments(from.size(), [&](Eigen::Index lo, Eigen::Index len) {
    to.segment(lo, len) = from.segment(lo, len);
  });
}

void parallel_copy(const std::vector<double>& from, std::vector<double>& to) {
  to.resize(from.size());
  parallel_for_ranges(int(from.size()), [&](int begin, int end) {
    std::copy(from.begin() + begin, from.begin() + end, to.begin() + begin);
  });
}

void parallel_zero(Eigen::Index n, Eigen::VectorXd& x) {
  x.resize(n);
  for_segments(n, [&](Eigen::Index lo, Eigen::Index len) { x.segment(lo, len).setZero(); });
}

void parallel_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b, Eigen::VectorXd& out) {
  out.resize(a.size());
  for_segments(a.size(), [&](Eigen::Index lo, Eigen::Index len) {
    out.segment(lo, len) = a.segment(lo, len) - b.segment(lo, len);
  });
}

}  // namespace granbench::twod

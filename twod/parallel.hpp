// Threads of the 2D solver and the rule that keeps its results independent of them.
//
// Every parallel loop of twod/ writes disjoint data (a column, a row, a block), and each element
// is computed by the same arithmetic as in a serial run, so the result does not depend on which
// thread computes it. Sums over the grid (the dot products and norms of conjugate gradients) are
// partial sums over a fixed partition of the index range into blocks of kBlock entries (the same
// for any thread count), each summed serially, then added in block order on one thread. So 1, 2
// or N threads give bitwise identical results (tests/twod/test_thread_invariance.cpp).
//
// The loops run on a ThreadTeam (thread_team.hpp) that belongs to the calling thread, not on
// OpenMP parallel regions: a step runs ~240 loops of a few microseconds each, and the team hands
// one out in a third of the time libgomp takes to open and close a region here.
//
// The thread count is OpenMP's setting: OMP_NUM_THREADS, or set_thread_count() (granbench
// --threads). It belongs to the calling thread, so a 2D run started on another std::thread has to
// be given it there (model_runs.cpp does). Built without OpenMP, the count is 1 unless set.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace granbench::twod {

// The number of threads a parallel region started by the calling thread will use.
int thread_count();
// Set it for the calling thread (n >= 1).
void set_thread_count(int n);

// A non-owning reference to a callable body(Args...), the body of a parallel loop (a plain
// function call, so that the threading stays in parallel.cpp).
template <class... Args>
class BodyRef {
 public:
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, BodyRef>)  // copies stay copies
      BodyRef(F&& f)  // NOLINT(google-explicit-constructor): lambdas convert where passed
      : object_(const_cast<void*>(static_cast<const void*>(&f))),
        call_([](void* o, Args... a) { (*static_cast<std::remove_reference_t<F>*>(o))(a...); }) {}
  // An empty reference (a thread team's slot for a loop not handed out); not callable.
  BodyRef() = default;
  void operator()(Args... a) const { call_(object_, a...); }
  explicit operator bool() const { return call_ != nullptr; }
  // The body's code, the same for every call of one loop (a thread team balances its shares
  // per loop with it).
  std::uintptr_t identity() const { return reinterpret_cast<std::uintptr_t>(call_); }

 private:
  void* object_ = nullptr;
  void (*call_)(void*, Args...) = nullptr;
};
using IndexBody = BodyRef<int>;       // body(i)
using RangeBody = BodyRef<int, int>;  // body(begin, end)

// body(i) for i in [0, n), on the calling thread's team (contiguous shares) when `parallel` is
// true and more than one thread is set; otherwise, or when called from inside another parallel
// loop, a plain loop on the calling thread.
void parallel_for(int n, bool parallel, IndexBody body);
// body(begin, end) once per thread with a non-empty contiguous share of [0, n) (body(0, n) on
// one thread): for element-wise loops, whose inner loop the compiler vectorises (a call per element
// through IndexBody would not be).
void parallel_for_ranges(int n, RangeBody body);

// The largest |v[n]| (exact in any order, so independent of the thread count).
double parallel_max_abs(const std::vector<double>& v);

// Fixed block length of the deterministic sums (entries): the 16 k - 32 k unknowns of a
// 256 x 64 grid give each of a few threads several blocks, and the serial combination of the
// partial sums costs nothing.
inline constexpr Eigen::Index kBlock = 1024;

// x . y summed over the fixed blocks (see above).
double deterministic_dot(const Eigen::VectorXd& x, const Eigen::VectorXd& y);
// The conjugate-gradient update x += alpha d, r -= alpha q; returns r . r (fixed blocks).
double cg_update(double alpha, const Eigen::VectorXd& d, const Eigen::VectorXd& q,
                 Eigen::VectorXd& x, Eigen::VectorXd& r);
// d = z + beta d.
void cg_direction(const Eigen::VectorXd& z, double beta, Eigen::VectorXd& d);
// Element-wise vector operations split over the threads (a serial copy or fill of a few 100 kB
// is where the other threads wait otherwise): to = from; x = 0 (resized to n); out = a - b.
void parallel_copy(const Eigen::VectorXd& from, Eigen::VectorXd& to);
void parallel_zero(Eigen::Index n, Eigen::VectorXd& x);
void parallel_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b, Eigen::VectorXd& out);
// to = from for the solver's std::vector fields.
void parallel_copy(const std::vector<double>& from, std::vector<double>& to);

}  // namespace granbench::twod

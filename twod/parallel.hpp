// Threads of the 2D solver (OpenMP) and the rule that keeps its results independent of them.
//
// Every parallel loop of twod/ writes disjoint data (a column, a row, a block), and each element
// is computed by the same arithmetic as in a serial run, so the result does not depend on which
// thread computes it. Sums over the grid (the dot products and norms of conjugate gradients) are
// not left to `omp reduction`, whose combination order follows the thread count and the
// schedule: they are partial sums over a fixed partition of the index range into blocks of
// kBlock entries (the same for any thread count), each summed serially, then added in block
// order on one thread. So 1, 2 or N threads give bitwise identical results
// (tests/twod/test_thread_invariance.cpp).
//
// The thread count is OpenMP's: OMP_NUM_THREADS, or set_thread_count() (granbench --threads). It
// belongs to the calling thread, so a 2D run started on another std::thread has to be given it
// there (model_runs.cpp does). Built without OpenMP, everything runs on one thread.
//
// No OpenMP pragma sits in a header: targets that include these headers are not compiled with
// -fopenmp (which would also switch on Eigen's own threading of dense products elsewhere).
#pragma once

#include <Eigen/Dense>
#include <type_traits>

namespace granbench::twod {

// The number of threads a parallel region started by the calling thread will use.
int thread_count();
// Set it for the calling thread (n >= 1).
void set_thread_count(int n);

// A non-owning reference to a callable body(int), the body of parallel_for (a plain function
// call, so that the pragma stays in parallel.cpp; see above).
class IndexBody {
 public:
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, IndexBody>)  // copies stay copies
      IndexBody(F&& f)  // NOLINT(google-explicit-constructor): lambdas convert where passed
      : object_(const_cast<void*>(static_cast<const void*>(&f))),
        call_([](void* o, int i) { (*static_cast<std::remove_reference_t<F>*>(o))(i); }) {}
  void operator()(int i) const { call_(object_, i); }

 private:
  void* object_;
  void (*call_)(void*, int);
};

// body(i) for i in [0, n), on the threads (static schedule) when `parallel` is true and more
// than one thread is set; otherwise a plain loop that does not enter OpenMP at all. (libgomp
// ends every parallel region, even a one-thread team or one with a false `if` clause, at a
// barrier that makes a futex system call: the ~480 regions of a 256 x 64 rollwave step, most of
// them on the multigrid's coarse levels, cost 6 % of a one-thread run in the kernel.)
void parallel_for(int n, bool parallel, IndexBody body);

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

}  // namespace granbench::twod

// A fixed team of threads that runs the 2D solver's parallel loops (parallel_for, parallel.hpp).
//
// Why not an OpenMP parallel region per loop: a 256 x 64 step runs about 240 such loops, most of
// them a few microseconds of work (multigrid line sweeps per colour and level, vector updates).
// On this project's 2-core machine libgomp takes 3.3 us to open and close an empty region for two
// threads, against 0.9 us for a hand-off through one atomic counter to a spinning worker, and its
// wake-ups made futex system calls inside the projection (docs/performance.md). The team keeps
// its workers spinning between loops for a short while, then lets them sleep (so an idle solver
// does not hold a core), and hands each loop out by bumping one counter.
//
// Each member always runs the same share of an index range (contiguous blocks like OpenMP's
// static schedule, or every size()-th index), and the loops of twod/ write disjoint data, so
// results do not depend on which thread ran what.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "twod/parallel.hpp"

namespace granbench::twod {

class ThreadTeam {
 public:
  // A team of `size` members: the calling thread and size - 1 workers started here.
  explicit ThreadTeam(int size);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  int size() const { return size_; }

  // body(i) for every i in [0, n), shared by the members; returns when all are done. The calling
  // thread must be the one that made the team. An exception thrown by body is rethrown here
  // (the first one seen) after every member has finished its share.
  void run(int n, Schedule schedule, IndexBody body);

  // Whether the calling thread is running a share of some team's loop (a loop started from
  // there runs serially: the team's members are all busy).
  static bool inside_a_loop();

 private:
  // The indices of member m: [begin, end) with stride step.
  struct Share {
    int begin, end, step;
  };
  Share share(int member) const;
  void run_share(int member) noexcept;
  void worker_loop(int member);

  int size_;
  std::vector<std::thread> workers_;
  // The loop being handed out (written by the caller before it bumps generation_).
  int n_ = 0;
  Schedule schedule_ = Schedule::Contiguous;
  const IndexBody* body_ = nullptr;
  bool stopping_ = false;
  std::exception_ptr error_;
  std::atomic<bool> has_error_{false};
  // Each counter on its own cache line: the workers poll generation_ while the caller polls
  // pending_.
  alignas(64) std::atomic<unsigned> generation_{0};
  alignas(64) std::atomic<int> pending_{0};
  alignas(64) std::atomic<int> sleepers_{0};
  // Where workers that found no loop for a while sleep (sleepers_ counts them).
  std::mutex sleep_mutex_;
  std::condition_variable wake_;
};

}  // namespace granbench::twod

// A fixed team of threads that runs the 2D solver's parallel loops (parallel_for, parallel.hpp).
//
// Why not an OpenMP parallel region per loop: a 256 x 64 step runs about 240 such loops, most of
// them a few microseconds of work (multigrid line sweeps per colour and level, vector updates).
// On this project's 2-core machine libgomp takes 3.3 us to open and close an empty region for two
// threads, against 0.9 us for a hand-off through one atomic counter to a spinning worker, and its
// wake-ups made futex system calls inside the projection (docs/performance.md). The team keeps
// its workers spinning between loops for a short while, then lets them sleep (so an idle solver
// does not hold a core), and hands each loop out through one cache line per worker. When the caller
// has waited a while for a worker that has not begun its share (more threads than free cores), it
// runs that share itself.
//
// A loop's shares follow the members' measured speeds at that loop (share_balance.hpp): equal at
// first, then in proportion to how fast each member got through its share on earlier calls. The
// loops of twod/ write disjoint data and compute each index by the same arithmetic whoever runs
// it, so results do not depend on which thread ran what, nor on the shares.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "twod/parallel.hpp"
#include "twod/share_balance.hpp"

namespace granbench::twod {

class ThreadTeam {
 public:
  // Whether the caller, done with its own share and kept waiting, runs a worker's share that the
  // worker has not begun (see run_loop). Never: for tests of the shares themselves.
  enum class TakeOver { WhenTheWorkerHasNotBegun, Never };

  // A team of `size` members: the calling thread and size - 1 workers started here.
  explicit ThreadTeam(int size, TakeOver take_over = TakeOver::WhenTheWorkerHasNotBegun);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  int size() const { return size_; }

  // body(i) for every i in [0, n), shared by the members; returns when all are done. The calling
  // thread must be the one that made the team. An exception thrown by body is rethrown here
  // (the first one seen) after every member has finished its share. `site` names the loop for
  // the balance of its shares (the body's code: BodyRef::identity()).
  void run(int n, IndexBody body, std::uintptr_t site);
  // body(begin, end) once per member with a non-empty contiguous share of [0, n).
  void run_ranges(int n, RangeBody body, std::uintptr_t site);

  // How many shares the caller ran for workers that had not taken them (see run_loop).
  std::uint64_t shares_taken_over() const { return shares_taken_over_; }

  // Whether the calling thread is running a share of some team's loop (a loop started from
  // there runs serially: the team's members are all busy).
  static bool inside_a_loop();

 private:
  // One member's share of a loop: body(i) for i in [begin, end), or range_body(begin, end).
  struct Share {
    int begin = 0, end = 0;
    IndexBody body;
    RangeBody range_body;
  };
  // What the caller hands one worker: the loop's generation and the worker's share, on one cache
  // line that the worker polls. With the cores far apart every line a worker has to fetch from
  // the caller's core costs a few hundred ns before it can start; with the loop's description
  // spread over the team's fields, the shares' bounds and the body on the caller's stack, an
  // empty loop took 1.2 us, and 0.6 us with the mailbox (docs/performance.md, forty-seventh
  // session).
  struct alignas(64) Mailbox {
    std::atomic<unsigned> generation{0};
    Share share;
  };
  // What a worker reports when its share is done, on one line that the caller polls: the
  // generation of the loop, and how many indices it ran in how long (for the balance).
  struct alignas(64) Report {
    std::atomic<unsigned> generation{0};
    int count = 0;
    std::uint64_t ticks = 0;
  };

  // Hands the loop (n indices, one of the two bodies) to the workers, runs member 0's share and
  // waits for the others.
  void run_loop(int n, IndexBody body, RangeBody range_body, std::uintptr_t site);
  // The shares' bounds from the balance's cumulative shares.
  void set_bounds(int n);
  // Runs a share; returns its ticks (ShareBalance::ticks_now). An exception is kept in error_.
  std::uint64_t run_share(const Share& share) noexcept;
  // Takes member's share of the loop of `generation` for the calling thread (the member itself,
  // or the caller for a worker that has not begun); false when someone has taken it already.
  bool claim(int member, unsigned generation);
  void worker_loop(int member);

  int size_;
  TakeOver take_over_;
  std::vector<std::thread> workers_;
  // Written by the caller only: the loops handed out so far, member m's share
  // [bounds_[m], bounds_[m + 1]), and which workers have finished the present loop.
  unsigned generation_ = 0;
  std::vector<int> bounds_;
  std::vector<double> cumulative_;
  std::vector<char> finished_;
  ShareBalance balance_;
  std::vector<int> counts_;  // (what each member did in the last loop, for the balance)
  std::vector<std::uint64_t> ticks_;
  std::vector<Mailbox> mailboxes_;  // [m] for worker m (entry 0 unused)
  std::vector<Report> reports_;     // [m] from worker m (entry 0 unused)
  // Per member, the generation of the last loop whose share someone took, each on its own cache
  // line.
  struct alignas(64) Claim {
    std::atomic<unsigned> generation{0};
  };
  std::vector<Claim> claims_;
  std::uint64_t shares_taken_over_ = 0;
  bool took_over_last_loop_ = false;
  bool stopping_ = false;
  std::exception_ptr error_;
  std::atomic<bool> has_error_{false};
  alignas(64) std::atomic<int> sleepers_{0};
  // Where workers that found no loop for a while sleep (sleepers_ counts them).
  std::mutex sleep_mutex_;
  std::condition_variable wake_;
};

}  // namespace granbench::twod

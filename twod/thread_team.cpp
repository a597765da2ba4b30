// The 2D solver's thread team; see thread_team.hpp.
#include "twod/thread_team.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace granbench::twod {

namespace {

// How long a worker polls for the next loop before it sleeps. The solver's serial stretches
// between loops are microseconds; a worker that finds nothing for this long is waiting on
// something else (output, the other model of `compare`, the end of the run).
constexpr auto kSpinBeforeSleep = std::chrono::microseconds(200);

// How many times the caller polls for its workers before it first looks for a share that no one
// has taken and lets other threads have its core: about 40 us at this machine's 19 ns per poll,
// longer than the imbalance at the end of most loops.
constexpr unsigned kPatientPolls = 2048;

// Set on a team's workers for their lifetime and on the calling thread while it runs a loop.
thread_local bool in_team_loop = false;

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

}  // namespace

ThreadTeam::ThreadTeam(int size, TakeOver take_over)
    : size_(size),
      take_over_(take_over),
      bounds_(std::size_t(std::max(size, 1)) + 1),
      cumulative_(std::size_t(std::max(size, 1)) + 1),
      balance_(std::max(size, 1)),
      records_(std::size_t(std::max(size, 1))),
      counts_(std::size_t(std::max(size, 1))),
      ticks_(std::size_t(std::max(size, 1))),
      claims_(std::size_t(std::max(size, 1))) {
  if (size < 1) throw std::invalid_argument("ThreadTeam: need size >= 1");
  workers_.reserve(std::size_t(size - 1));
  for (int m = 1; m < size; ++m) workers_.emplace_back([this, m] { worker_loop(m); });
}

ThreadTeam::~ThreadTeam() {
  stopping_ = true;
  generation_.fetch_add(1, std::memory_order_seq_cst);
  {
    std::lock_guard<std::mutex> lock(sleep_mutex_);
    wake_.notify_all();
  }
  for (std::thread& t : workers_) t.join();
}

void ThreadTeam::set_bounds() {
  const int n = n_;
  if (n < size_) {  // one index each for the first n members
    for (int m = 0; m <= size_; ++m) bounds_[std::size_t(m)] = std::min(m, n);
    return;
  }
  // every member at least one index, so that each is timed and the shares can move back
  bounds_[0] = 0;
  for (int m = 1; m < size_; ++m) {
    int b = int(std::lround(n * cumulative_[std::size_t(m)]));
    b = std::max(b, bounds_[std::size_t(m) - 1] + 1);
    bounds_[std::size_t(m)] = std::min(b, n - (size_ - m));
  }
  bounds_[std::size_t(size_)] = n;
}

void ThreadTeam::run_share(int member) noexcept {
  const std::uint64_t start = ShareBalance::ticks_now();
  int count = 0;
  try {
    const std::size_t m = std::size_t(member);
    const int begin = bounds_[m], end = bounds_[m + 1];
    count = end - begin;
    if (range_body_ != nullptr) {
      if (begin < end) (*range_body_)(begin, end);
    } else {
      for (int i = begin; i < end; ++i) (*body_)(i);
    }
  } catch (...) {
    if (!has_error_.exchange(true)) error_ = std::current_exception();
  }
  records_[std::size_t(member)].count = count;
  records_[std::size_t(member)].ticks = ShareBalance::ticks_now() - start;
}

void ThreadTeam::run(int n, IndexBody body, std::uintptr_t site) {
  n_ = n;
  body_ = &body;
  range_body_ = nullptr;
  run_loop(site);
}

void ThreadTeam::run_ranges(int n, RangeBody body, std::uintptr_t site) {
  n_ = n;
  body_ = nullptr;
  range_body_ = &body;
  run_loop(site);
}

void ThreadTeam::run_loop(std::uintptr_t site) {
  const int slot = balance_.shares(site, n_, cumulative_.data());
  set_bounds();
  in_team_loop = true;
  pending_.store(size_ - 1, std::memory_order_relaxed);
  // seq_cst, paired with the worker's sleepers_ increment: either we see it and wake the worker,
  // or the worker's wait sees the new generation and does not sleep.
  const unsigned generation = generation_.fetch_add(1, std::memory_order_seq_cst) + 1;
  if (sleepers_.load(std::memory_order_seq_cst) > 0) {
    std::lock_guard<std::mutex> lock(sleep_mutex_);  // (held by a worker until it waits)
    wake_.notify_all();
  }
  run_share(0);
  // Wait for the workers. With more threads than free cores (another program, or compare's
  // depth-averaged model beside the team) a worker may not be running at all, and waiting for it
  // costs two thread switches per loop; so before the caller lets other threads have its core, it
  // runs the shares whose members have not taken them yet. It looks at once when it took a share
  // over in the last loop, and otherwise only after kPatientPolls: reading a worker's claim
  // makes the worker's next claim move the cache line back across the cores (which, looked at
  // after 64 or 256 polls, 1-5 us here, cost 2-8 % of a step with the two cores far apart).
  const bool may_take_over = take_over_ == TakeOver::WhenTheWorkerHasNotBegun;
  const bool look_at_once = took_over_last_loop_;
  took_over_last_loop_ = false;
  for (unsigned spins = 0; pending_.load(std::memory_order_acquire) != 0; ++spins) {
    const bool now_and_then = spins >= kPatientPolls && (spins - kPatientPolls) % 256 == 0;
    if (!now_and_then && !(look_at_once && spins == 0)) {
      cpu_relax();
      continue;
    }
    for (int m = 1; m < size_ && may_take_over; ++m)
      if (claim(m, generation)) {
        run_share(m);
        pending_.fetch_sub(1, std::memory_order_release);
        ++shares_taken_over_;
        took_over_last_loop_ = true;
      }
    // (a worker preempted in its share gets its core back sooner)
    if (now_and_then && pending_.load(std::memory_order_acquire) != 0) std::this_thread::yield();
  }
  body_ = nullptr;
  range_body_ = nullptr;
  in_team_loop = false;
  for (std::size_t m = 0; m < records_.size(); ++m) {
    counts_[m] = records_[m].count;
    ticks_[m] = records_[m].ticks;
  }
  // (a share the caller took over says nothing of its member's speed)
  if (!took_over_last_loop_) balance_.record(slot, counts_.data(), ticks_.data());
  if (has_error_.load(std::memory_order_relaxed)) {
    has_error_ = false;
    std::rethrow_exception(std::exchange(error_, nullptr));
  }
}

bool ThreadTeam::claim(int member, unsigned generation) {
  std::atomic<unsigned>& last = claims_[std::size_t(member)].generation;
  unsigned claimed = last.load(std::memory_order_acquire);
  // Claims only move forward: a worker that read an older generation must not take a share of a
  // later loop that the caller has taken already (the difference is signed, so that the
  // counter's wrap-around keeps the order).
  while (int(claimed - generation) < 0)
    if (last.compare_exchange_weak(claimed, generation, std::memory_order_acq_rel)) return true;
  return false;
}

bool ThreadTeam::inside_a_loop() {
  return in_team_loop;
}

void ThreadTeam::worker_loop(int member) {
  in_team_loop = true;
  unsigned seen = 0;  // the generation at construction (a loop may be handed out before we start)
  while (true) {
    unsigned now = generation_.load(std::memory_order_acquire);
    if (now == seen) {
      const auto since = std::chrono::steady_clock::now();
      for (unsigned spins = 1; now == seen; ++spins) {
        cpu_relax();
        now = generation_.load(std::memory_order_acquire);
        if (now != seen || spins % 256 != 0) continue;
        if (std::chrono::steady_clock::now() - since > kSpinBeforeSleep) {
          std::unique_lock<std::mutex> lock(sleep_mutex_);
          sleepers_.fetch_add(1, std::memory_order_seq_cst);
          while ((now = generation_.load(std::memory_order_seq_cst)) == seen) wake_.wait(lock);
          sleepers_.fetch_sub(1, std::memory_order_relaxed);
        } else {
          // Polling without yielding held the core for its whole 200 us whenever another thread
          // waited for it (more threads than free cores): the caller of the team then stalled
          // in every loop.
          std::this_thread::yield();
        }
      }
    }
    seen = now;
    if (stopping_) return;
    if (!claim(member, now)) continue;  // (the caller ran it)
    run_share(member);
    pending_.fetch_sub(1, std::memory_order_release);
  }
}

}  // namespace granbench::twod

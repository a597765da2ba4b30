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
      finished_(std::size_t(std::max(size, 1))),
      balance_(std::max(size, 1)),
      counts_(std::size_t(std::max(size, 1))),
      ticks_(std::size_t(std::max(size, 1))),
      mailboxes_(std::size_t(std::max(size, 1))),
      reports_(std::size_t(std::max(size, 1))),
      claims_(std::size_t(std::max(size, 1))) {
  if (size < 1) throw std::invalid_argument("ThreadTeam: need size >= 1");
  workers_.reserve(std::size_t(size - 1));
  for (int m = 1; m < size; ++m) workers_.emplace_back([this, m] { worker_loop(m); });
}

ThreadTeam::~ThreadTeam() {
  stopping_ = true;
  ++generation_;
  for (int m = 1; m < size_; ++m)
    mailboxes_[std::size_t(m)].generation.store(generation_, std::memory_order_seq_cst);
  {
    std::lock_guard<std::mutex> lock(sleep_mutex_);
    wake_.notify_all();
  }
  for (std::thread& t : workers_) t.join();
}

void ThreadTeam::set_bounds(int n) {
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

std::uint64_t ThreadTeam::run_share(const Share& share) noexcept {
  const std::uint64_t start = ShareBalance::ticks_now();
  try {
    if (share.range_body) {
      if (share.begin < share.end) share.range_body(share.begin, share.end);
    } else {
      for (int i = share.begin; i < share.end; ++i) share.body(i);
    }
  } catch (...) {
    if (!has_error_.exchange(true)) error_ = std::current_exception();
  }
  return ShareBalance::ticks_now() - start;
}

void ThreadTeam::run(int n, IndexBody body, std::uintptr_t site) {
  run_loop(n, body, RangeBody{}, site);
}

void ThreadTeam::run_ranges(int n, RangeBody body, std::uintptr_t site) {
  run_loop(n, IndexBody{}, body, site);
}

void ThreadTeam::run_loop(int n, IndexBody body, RangeBody range_body, std::uintptr_t site) {
  const int slot = balance_.shares(site, n, cumulative_.data());
  set_bounds(n);
  in_team_loop = true;
  const unsigned generation = ++generation_;
  // Each worker's share into its mailbox, then the generation that tells it so.
  for (int m = 1; m < size_; ++m) {
    Mailbox& box = mailboxes_[std::size_t(m)];
    box.share = Share{bounds_[std::size_t(m)], bounds_[std::size_t(m) + 1], body, range_body};
    box.generation.store(generation, std::memory_order_release);
  }
  // Workers asleep for a while are woken now (their count is long visible here). One that is
  // just falling asleep may not be counted yet; the check after the caller's share catches it.
  const auto wake_sleepers = [this] {
    std::lock_guard<std::mutex> lock(sleep_mutex_);  // (held by a worker until it waits)
    wake_.notify_all();
  };
  if (sleepers_.load(std::memory_order_relaxed) > 0) wake_sleepers();
  counts_[0] = bounds_[1] - bounds_[0];
  ticks_[0] = run_share(Share{bounds_[0], bounds_[1], body, range_body});
  // The fence pairs with the worker's seq_cst sleepers_ increment: either we see it and wake the
  // worker, or the worker's wait sees the new generation and does not sleep. Before the caller's
  // own share it would stall the caller until the mailboxes' lines had come over from the
  // workers' core (a round trip, 0.4 us with the cores far apart); after it, they have.
  std::atomic_thread_fence(std::memory_order_seq_cst);
  // (a worker woken above may still be counted: it is told twice, which costs nothing here)
  if (sleepers_.load(std::memory_order_relaxed) > 0) wake_sleepers();
  // Wait for the workers' reports. With more threads than free cores (another program, or
  // compare's depth-averaged model beside the team) a worker may not be running at all, and
  // waiting for it costs two thread switches per loop; so before the caller lets other threads
  // have its core, it runs the shares whose members have not taken them yet. It looks at once
  // when it took a share over in the last loop, and otherwise only after kPatientPolls: reading a
  // worker's claim makes the worker's next claim move the cache line back across the cores
  // (which, looked at after 64 or 256 polls, 1-5 us here, cost 2-8 % of a step with the two
  // cores far apart).
  const bool may_take_over = take_over_ == TakeOver::WhenTheWorkerHasNotBegun;
  const bool look_at_once = took_over_last_loop_;
  took_over_last_loop_ = false;
  int remaining = size_ - 1;
  std::fill(finished_.begin(), finished_.end(), char(0));
  for (unsigned spins = 0;; ++spins) {
    for (int m = 1; m < size_; ++m) {
      const std::size_t w = std::size_t(m);
      if (finished_[w] || reports_[w].generation.load(std::memory_order_acquire) != generation)
        continue;
      finished_[w] = 1;
      --remaining;
      counts_[w] = reports_[w].count;
      ticks_[w] = reports_[w].ticks;
    }
    if (remaining == 0) break;
    const bool now_and_then = spins >= kPatientPolls && (spins - kPatientPolls) % 256 == 0;
    if (!now_and_then && !(look_at_once && spins == 0)) {
      cpu_relax();
      continue;
    }
    for (int m = 1; m < size_ && may_take_over; ++m) {
      const std::size_t w = std::size_t(m);
      if (finished_[w] || !claim(m, generation)) continue;
      run_share(mailboxes_[w].share);  // (the caller wrote it; the worker no longer reads it)
      finished_[w] = 1;
      --remaining;
      ++shares_taken_over_;
      took_over_last_loop_ = true;
    }
    // (a worker preempted in its share gets its core back sooner)
    if (now_and_then && remaining != 0) std::this_thread::yield();
  }
  in_team_loop = false;
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
  Mailbox& box = mailboxes_[std::size_t(member)];
  Report& report = reports_[std::size_t(member)];
  unsigned seen = 0;  // the generation at construction (a loop may be handed out before we start)
  while (true) {
    unsigned now = box.generation.load(std::memory_order_acquire);
    if (now == seen) {
      const auto since = std::chrono::steady_clock::now();
      for (unsigned spins = 1; now == seen; ++spins) {
        cpu_relax();
        now = box.generation.load(std::memory_order_acquire);
        if (now != seen || spins % 256 != 0) continue;
        if (std::chrono::steady_clock::now() - since > kSpinBeforeSleep) {
          std::unique_lock<std::mutex> lock(sleep_mutex_);
          sleepers_.fetch_add(1, std::memory_order_seq_cst);
          while ((now = box.generation.load(std::memory_order_seq_cst)) == seen) wake_.wait(lock);
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
    // Claimed first, then read: once this worker holds the claim the caller waits for its report
    // and does not write the mailbox again; a claim that fails (the caller ran the share, and
    // may be writing the next loop's) leaves the mailbox unread.
    if (!claim(member, now)) continue;
    const Share share = box.share;
    const std::uint64_t ticks = run_share(share);
    report.count = share.end - share.begin;
    report.ticks = ticks;
    report.generation.store(now, std::memory_order_release);
  }
}

}  // namespace granbench::twod

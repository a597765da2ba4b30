// The 2D solver's thread team; see thread_team.hpp.
#include "twod/thread_team.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

namespace granbench::twod {

namespace {

// How long a worker polls for the next loop before it sleeps. The solver's serial stretches
// between loops are microseconds; a worker that finds nothing for this long is waiting on
// something else (output, the other model of `compare`, the end of the run).
constexpr auto kSpinBeforeSleep = std::chrono::microseconds(200);

// Set on a team's workers for their lifetime and on the calling thread while it runs a loop.
thread_local bool in_team_loop = false;

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

}  // namespace

ThreadTeam::ThreadTeam(int size) : size_(size) {
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

ThreadTeam::Share ThreadTeam::share(int member) const {
  if (schedule_ == Schedule::Interleaved) return {member, n_, size_};
  // contiguous blocks, the first n % size members one index longer (OpenMP's static schedule)
  const int q = n_ / size_, r = n_ % size_;
  const int begin = member * q + std::min(member, r);
  return {begin, begin + q + (member < r ? 1 : 0), 1};
}

void ThreadTeam::run_share(int member) noexcept {
  try {
    const Share s = share(member);
    for (int i = s.begin; i < s.end; i += s.step) (*body_)(i);
  } catch (...) {
    if (!has_error_.exchange(true)) error_ = std::current_exception();
  }
}

void ThreadTeam::run(int n, Schedule schedule, IndexBody body) {
  n_ = n;
  schedule_ = schedule;
  body_ = &body;
  in_team_loop = true;
  pending_.store(size_ - 1, std::memory_order_relaxed);
  // seq_cst, paired with the worker's sleepers_ increment: either we see it and wake the worker,
  // or the worker's wait sees the new generation and does not sleep.
  generation_.fetch_add(1, std::memory_order_seq_cst);
  if (sleepers_.load(std::memory_order_seq_cst) > 0) {
    std::lock_guard<std::mutex> lock(sleep_mutex_);  // (held by a worker until it waits)
    wake_.notify_all();
  }
  run_share(0);
  // The workers' shares are as long as ours; when the team shares the machine with other
  // threads (compare runs both models at once), let them have the core now and then.
  for (unsigned spins = 0; pending_.load(std::memory_order_acquire) != 0; ++spins) {
    if (spins % 4096 == 4095)
      std::this_thread::yield();
    else
      cpu_relax();
  }
  body_ = nullptr;
  in_team_loop = false;
  if (has_error_.load(std::memory_order_relaxed)) {
    has_error_ = false;
    std::rethrow_exception(std::exchange(error_, nullptr));
  }
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
        if (now == seen && spins % 256 == 0 &&
            std::chrono::steady_clock::now() - since > kSpinBeforeSleep) {
          std::unique_lock<std::mutex> lock(sleep_mutex_);
          sleepers_.fetch_add(1, std::memory_order_seq_cst);
          while ((now = generation_.load(std::memory_order_seq_cst)) == seen) wake_.wait(lock);
          sleepers_.fetch_sub(1, std::memory_order_relaxed);
        }
      }
    }
    seen = now;
    if (stopping_) return;
    run_share(member);
    pending_.fetch_sub(1, std::memory_order_release);
  }
}

}  // namespace granbench::twod

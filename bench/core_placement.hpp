// How far apart the host has placed this process's cores, for the benchmarks that time threads
// (bench_twod_rollwave, bench_thread_handoff). On this project's 2-core virtual machine the
// round trip of one cache line between two threads is 110-180 ns in some hours and 400-900 ns in
// others, and every two-thread figure follows it (docs/performance.md).
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sched.h>
#endif

namespace granbench::bench {

// The CPUs this process may run on (its affinity mask, e.g. under taskset), which can be fewer
// than the machine's hardware threads.
inline int available_cpus() {
#ifdef __linux__
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return CPU_COUNT(&set);
#endif
  return int(std::max(1u, std::thread::hardware_concurrency()));
}

// Round trip of one cache line between two threads (each waits for the other's store), in ns:
// the median of 9 repetitions of 100 000 round trips. Both threads spin without yielding, so it
// needs two CPUs: on one, every trip would wait for the scheduler to switch threads (minutes).
inline double core_round_trip_ns() {
  std::vector<double> times;
  for (int rep = 0; rep < 9; ++rep) {
    constexpr int kTrips = 100000;
    alignas(64) std::atomic<int> ball{0};
    std::thread partner([&] {
      for (int i = 0; i < kTrips; ++i) {
        while (ball.load(std::memory_order_acquire) != 2 * i + 1) {
        }
        ball.store(2 * i + 2, std::memory_order_release);
      }
    });
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < kTrips; ++i) {
      ball.store(2 * i + 1, std::memory_order_release);
      while (ball.load(std::memory_order_acquire) != 2 * i + 2) {
      }
    }
    times.push_back(
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() /
        kTrips);
    partner.join();
  }
  std::nth_element(times.begin(), times.begin() + 4, times.end());
  return times[4];
}

// The CPUs of this process's affinity mask, in order.
inline std::vector<int> allowed_cpus() {
  std::vector<int> cpus;
#ifdef __linux__
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) == 0)
    for (int c = 0; c < CPU_SETSIZE; ++c)
      if (CPU_ISSET(c, &set)) cpus.push_back(c);
#endif
  return cpus;
}

// Let the calling thread run only on `cpus` (one CPU to pin it; allowed_cpus() as it was to undo
// that); false where that is not possible (not Linux, or the kernel refused).
inline bool pin_calling_thread(const std::vector<int>& cpus) {
#ifdef __linux__
  cpu_set_t set;
  CPU_ZERO(&set);
  for (int c : cpus) CPU_SET(c, &set);
  return sched_setaffinity(0, sizeof(set), &set) == 0;
#else
  (void)cpus;
  return false;
#endif
}

}  // namespace granbench::bench

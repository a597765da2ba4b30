// The thread team under the 2D solver's parallel loops (twod/thread_team.hpp, parallel.hpp):
// every index visited exactly once by each kind of loop, for any thread count and range length;
// a loop started inside another runs on the calling thread; an exception thrown in any member's
// share reaches the caller and leaves the team usable; changing the thread count remakes it; a
// worker that does not get a core has its shares run by the caller.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sched.h>
#endif

#include "twod/parallel.hpp"
#include "twod/thread_team.hpp"

using namespace granbench::twod;

namespace {

// Waits until `flag` is set, for at most 10 s; returns whether it was. (The caller of a loop may
// run a worker's share that the worker has not begun: a caller's index that waits for one of the
// worker's makes sure that the worker ran its own share.)
bool wait_for(const std::atomic<bool>& flag) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!flag.load() && std::chrono::steady_clock::now() < until) std::this_thread::yield();
  return flag.load();
}

// Restores the calling thread's thread count when a test ends.
class ThreadCountGuard {
 public:
  ThreadCountGuard() : saved_(thread_count()) {}
  ~ThreadCountGuard() { set_thread_count(saved_); }

 private:
  int saved_;
};

}  // namespace

TEST(ThreadTeam, EveryLoopVisitsEveryIndexOnce) {
  ThreadCountGuard guard;
  for (int threads : {1, 2, 3, 2})
    for (int n : {0, 1, 2, 7, 1000}) {
      SCOPED_TRACE(testing::Message() << threads << " threads, n " << n);
      set_thread_count(threads);
      for (bool parallel : {false, true}) {
        std::vector<int> visits(n, 0);
        parallel_for(n, parallel, [&](int i) { ++visits[i]; });
        EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), n) << "parallel " << parallel;
      }
      std::vector<int> visits(n, 0);
      std::atomic<int> ranges{0};
      parallel_for_ranges(n, [&](int begin, int end) {
        ++ranges;
        EXPECT_LE(0, begin);
        EXPECT_LE(begin, end);
        EXPECT_LE(end, n);
        for (int i = begin; i < end; ++i) ++visits[i];
      });
      EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), n) << "ranges";
      EXPECT_EQ(ranges.load(), n > 1 ? std::min(threads, n) : 1) << "one range per thread";
    }
}

TEST(ThreadTeam, WorkIsSharedAmongTheThreads) {
  // (a team whose caller never runs its worker's share, as in the next test)
  ThreadTeam team(2, ThreadTeam::TakeOver::Never);
  const std::thread::id caller = std::this_thread::get_id();
  // a loop's first call has equal shares: contiguous, the caller takes the first half and the
  // worker the second
  std::vector<std::thread::id> ran_on(64);
  auto record = [&](int i) { ran_on[i] = std::this_thread::get_id(); };
  const IndexBody body = record;
  team.run(64, body, body.identity());
  EXPECT_TRUE(
      std::all_of(ran_on.begin(), ran_on.begin() + 32, [&](auto id) { return id == caller; }));
  EXPECT_TRUE(
      std::none_of(ran_on.begin() + 32, ran_on.end(), [&](auto id) { return id == caller; }));
}

TEST(ThreadTeam, AMemberThatRunsSlowerGetsASmallerShare) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "needs two cores";
  // A team whose caller never runs its worker's share: under load (ctest runs two tests at once)
  // a worker without a core would leave its share to the caller, and this test is about the
  // shares the members get.
  ThreadTeam team(2, ThreadTeam::TakeOver::Never);
  const std::thread::id caller = std::this_thread::get_id();
  // every index costs ~1 us on the caller and six times that on the worker: the worker's share
  // settles near a seventh of the range. Judged by the median of the later calls, so that a call
  // disturbed by another process (ctest runs two at once) does not decide.
  auto spin = [](std::chrono::nanoseconds d) {
    const auto until = std::chrono::steady_clock::now() + d;
    while (std::chrono::steady_clock::now() < until) {
    }
  };
  constexpr int n = 400;
  std::vector<int> visits(n);
  std::atomic<int> on_worker{0};
  auto body = [&](int i) {
    ++visits[i];
    const bool worker = std::this_thread::get_id() != caller;
    if (worker) ++on_worker;
    spin(std::chrono::microseconds(worker ? 6 : 1));
  };
  std::vector<int> worker_share;
  for (int call = 0; call < 30; ++call) {
    std::fill(visits.begin(), visits.end(), 0);
    on_worker = 0;
    const IndexBody loop = body;
    team.run(n, loop, loop.identity());
    ASSERT_EQ(std::count(visits.begin(), visits.end(), 1), n) << "call " << call;
    if (call >= 10) worker_share.push_back(on_worker.load());
  }
  std::nth_element(worker_share.begin(), worker_share.begin() + 10, worker_share.end());
  const int median = worker_share[10];
  EXPECT_LT(median, n * 4 / 10) << "equal shares would give " << n / 2;
  EXPECT_GT(median, 0) << "every member keeps at least one index";
}

TEST(ThreadTeam, ALoopInsideALoopRunsOnTheCallingThread) {
  ThreadCountGuard guard;
  set_thread_count(2);
  std::vector<int> nested_elsewhere(8, 0), visits(8 * 16, 0);
  parallel_for(8, true, [&](int i) {
    const std::thread::id outer = std::this_thread::get_id();
    parallel_for(16, true, [&](int j) {
      ++visits[16 * i + j];
      if (std::this_thread::get_id() != outer) nested_elsewhere[i] = 1;
    });
  });
  EXPECT_EQ(std::count(nested_elsewhere.begin(), nested_elsewhere.end(), 1), 0);
  EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), 8 * 16);
}

TEST(ThreadTeam, AnExceptionInAnyShareReachesTheCaller) {
  ThreadCountGuard guard;
  set_thread_count(2);
  for (int thrower : {0, 99}) {  // in the caller's share, in the worker's
    SCOPED_TRACE(testing::Message() << "thrown at index " << thrower);
    std::atomic<int> visited{0};
    EXPECT_THROW(parallel_for(100, true,
                              [&](int i) {
                                ++visited;
                                if (i == thrower) throw std::runtime_error("bad cell");
                              }),
                 std::runtime_error);
    EXPECT_GE(visited.load(), 2);     // both members ran (the thrower stops its own share only)
    std::vector<int> visits(100, 0);  // the team still works
    parallel_for(100, true, [&](int i) { ++visits[i]; });
    EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), 100);
  }
}

TEST(ThreadTeam, AWorkerThatSleptWakesForTheNextLoop) {
  ThreadCountGuard guard;
  set_thread_count(2);
  std::vector<int> visits(10, 0);
  parallel_for(10, true, [&](int i) { ++visits[i]; });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // longer than the worker spins
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> worker_ran{false};
  parallel_for(10, true, [&](int i) {
    ++visits[i];
    if (std::this_thread::get_id() != caller)
      worker_ran = true;
    else
      wait_for(worker_ran);
  });
  EXPECT_EQ(std::count(visits.begin(), visits.end(), 2), 10);
  EXPECT_TRUE(worker_ran.load());
}

#ifdef __linux__
TEST(ThreadTeam, TheCallerRunsTheSharesOfAWorkerThatHasNoCore) {
  // Both of the team's threads on one CPU (the worker inherits the affinity of the thread that
  // starts it): while the caller runs, its worker cannot, so waiting for it would cost two thread
  // switches per loop. The caller takes such shares over; every index is still visited once.
  cpu_set_t saved, one;
  ASSERT_EQ(sched_getaffinity(0, sizeof(saved), &saved), 0);
  int cpu = 0;
  while (!CPU_ISSET(cpu, &saved)) ++cpu;
  CPU_ZERO(&one);
  CPU_SET(cpu, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof(one), &one), 0);
  std::uint64_t taken_over = 0;
  {
    ThreadTeam team(2);
    constexpr int n = 64;
    std::vector<int> visits(n);
    auto visit = [&](int i) { ++visits[i]; };
    const IndexBody body = visit;  // (a reference to `visit`)
    for (int call = 0; call < 200; ++call) {
      std::fill(visits.begin(), visits.end(), 0);
      team.run(n, body, body.identity());
      ASSERT_EQ(std::count(visits.begin(), visits.end(), 1), n) << "call " << call;
    }
    taken_over = team.shares_taken_over();
  }
  sched_setaffinity(0, sizeof(saved), &saved);
  EXPECT_GT(taken_over, 0u);
}
#endif

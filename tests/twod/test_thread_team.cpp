// The thread team under the 2D solver's parallel loops (twod/thread_team.hpp, parallel.hpp):
// every index visited exactly once by each kind of loop, for any thread count and range length;
// a loop started inside another runs on the calling thread; an exception thrown in any member's
// share reaches the caller and leaves the team usable; changing the thread count remakes it.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "twod/parallel.hpp"
#include "twod/thread_team.hpp"

using namespace granbench::twod;

namespace {

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
      parallel_for_interleaved(n, [&](int i) { ++visits[i]; });
      EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), n) << "interleaved";
      std::fill(visits.begin(), visits.end(), 0);
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
  ThreadCountGuard guard;
  set_thread_count(2);
  std::vector<std::thread::id> ran_on(64);
  parallel_for(64, true, [&](int i) { ran_on[i] = std::this_thread::get_id(); });
  const std::thread::id caller = std::this_thread::get_id();
  // contiguous shares: the caller takes the first half, the worker the second
  EXPECT_TRUE(
      std::all_of(ran_on.begin(), ran_on.begin() + 32, [&](auto id) { return id == caller; }));
  EXPECT_TRUE(
      std::none_of(ran_on.begin() + 32, ran_on.end(), [&](auto id) { return id == caller; }));
  parallel_for_interleaved(64, [&](int i) { ran_on[i] = std::this_thread::get_id(); });
  for (int i = 0; i < 64; ++i) EXPECT_EQ(ran_on[i] == caller, i % 2 == 0) << i;
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
  parallel_for(10, true, [&](int i) { ++visits[i]; });
  EXPECT_EQ(std::count(visits.begin(), visits.end(), 2), 10);
}

// How a thread team divides a loop among its members when they do not run at the same speed.
//
// Why: on this project's 2-core virtual machine the host sometimes places the two virtual cores
// far apart (a core-to-core round trip of 450-500 ns instead of 100-180 ns), and then the worker
// thread runs the same share about a third slower than the calling thread (per-loop timings,
// docs/performance.md, thirty-fourth session); equal shares leave the calling thread waiting at
// the end of every loop. Loops whose work varies along the index range (the rows of the
// viscosity, granular below the surface and light fluid above) need unequal shares too.
//
// The balance keeps, for each loop site (the loop body's code and the range's length), every
// member's speed in indices per clock tick, measured on its own share and averaged
// exponentially over the site's calls, and gives each member a share in proportion to it. Which
// member computes an index never changes the arithmetic done for it (parallel.hpp), so the
// results stay bitwise the same for any shares.
#pragma once

#include <cstdint>
#include <vector>

namespace granbench::twod {

class ShareBalance {
 public:
  explicit ShareBalance(int members);

  // The cumulative shares of a loop at `site` over n indices: cumulative[0] = 0 <= cumulative[1]
  // <= ... <= cumulative[members] = 1, member m taking the fraction cumulative[m + 1] -
  // cumulative[m]. Equal until the site has been measured. Returns the site's slot for record(),
  // or -1 when the table is full (the shares then stay equal).
  int shares(std::uintptr_t site, int n, double* cumulative);

  // What each member did in the slot's loop: counts[m] indices in ticks[m] clock ticks. Shares
  // under kMinTicks are too short to time, and those over kMaxTicks mistimed; either leaves the
  // speeds as they were.
  void record(int slot, const int* counts, const std::uint64_t* ticks);

  // The clock the members time their shares with (the time-stamp counter where there is one:
  // a few nanoseconds per reading, against 20-30 for the system clock here).
  static std::uint64_t ticks_now();
  static constexpr std::uint64_t kMinTicks = 4000;  // ~1.9 us at this machine's 2.1 GHz
  // Longer than any share (minutes): a thread moved to another core whose counter is not in step
  // (this host's kernel marks the counter unstable) can read a negative, i.e. huge, difference.
  static constexpr std::uint64_t kMaxTicks = std::uint64_t(1) << 40;

 private:
  static constexpr int kSlots = 1024;  // loop sites x lengths seen by one team (~100 in a run)
  static constexpr double kAveraging = 0.25;  // weight of the newest measurement
  int members_;
  std::vector<std::uint64_t> keys_;  // per slot: 0 when free
  std::vector<double> speed_;        // per slot and member: indices per tick (0: not measured)
};

}  // namespace granbench::twod

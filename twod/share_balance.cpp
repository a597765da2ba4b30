// Shares of a loop in proportion to the members' measured speeds; see share_balance.hpp.
#include "twod/share_balance.hpp"

#include <algorithm>
#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace granbench::twod {

ShareBalance::ShareBalance(int members)
    : members_(members),
      keys_(kSlots, 0),
      speed_(std::size_t(kSlots) * std::size_t(members), 0.0) {}

std::uint64_t ShareBalance::ticks_now() {
#if defined(__x86_64__) || defined(__i386__)
  return __rdtsc();
#else
  return std::uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(
                           std::chrono::steady_clock::now().time_since_epoch())
                           .count());
#endif
}

int ShareBalance::shares(std::uintptr_t site, int n, double* cumulative) {
  for (int m = 0; m <= members_; ++m) cumulative[m] = double(m) / members_;
  // open addressing on (site, n); 0 marks a free slot, so the key is never 0
  const std::uint64_t key = (std::uint64_t(site) ^ (std::uint64_t(unsigned(n)) << 48)) | 1u;
  std::uint64_t h = key * 0x9E3779B97F4A7C15ull;
  for (int probe = 0; probe < 16; ++probe, h += 0x9E3779B97F4A7C15ull) {
    const int slot = int(h >> 54) % kSlots;  // (the top 10 bits)
    if (keys_[std::size_t(slot)] == 0) keys_[std::size_t(slot)] = key;
    if (keys_[std::size_t(slot)] != key) continue;
    const double* s = &speed_[std::size_t(slot) * std::size_t(members_)];
    double total = 0.0;
    for (int m = 0; m < members_; ++m) {
      if (s[m] <= 0.0) return slot;  // not measured yet: equal shares
      total += s[m];
    }
    double sum = 0.0;
    for (int m = 0; m < members_; ++m) {
      sum += s[m];
      cumulative[m + 1] = m + 1 == members_ ? 1.0 : sum / total;
    }
    return slot;
  }
  return -1;
}

void ShareBalance::record(int slot, const int* counts, const std::uint64_t* ticks) {
  if (slot < 0) return;
  for (int m = 0; m < members_; ++m)
    if (counts[m] < 1 || ticks[m] < kMinTicks || ticks[m] > kMaxTicks) return;
  double* s = &speed_[std::size_t(slot) * std::size_t(members_)];
  // A member preempted by the host for a while must not lose its share for good: each measured
  // speed is kept within a factor of 4 of the others' mean.
  double mean = 0.0;
  for (int m = 0; m < members_; ++m) mean += double(counts[m]) / double(ticks[m]) / members_;
  for (int m = 0; m < members_; ++m) {
    const double rate = std::clamp(double(counts[m]) / double(ticks[m]), mean / 4, mean * 4);
    s[m] = s[m] > 0.0 ? (1.0 - kAveraging) * s[m] + kAveraging * rate : rate;
  }
}

}  // namespace granbench::twod

// The command's heap (heap_pages.hpp): after use_huge_pages_for_the_heap(), a block of a few
// MiB comes from the heap, not from a mapping of its own, and where the kernel gives huge pages on
// request, part of the heap is marked for them.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/cli/heap_pages.hpp"

namespace {

struct Mapping {
  std::uintptr_t begin = 0, end = 0;
  std::string name;
  bool huge_page_eligible = false;  // smaps' THPeligible
};

// The process's mappings with their names and huge-page eligibility, from /proc/self/smaps.
std::vector<Mapping> mappings() {
  std::ifstream smaps("/proc/self/smaps");
  std::vector<Mapping> list;
  std::string line;
  while (std::getline(smaps, line)) {
    std::istringstream in(line);
    std::string range, field;
    in >> range;
    const auto dash = range.find('-');
    if (dash != std::string::npos && line.find(':') > dash && std::isxdigit(line[0])) {
      Mapping m;
      m.begin = std::stoull(range.substr(0, dash), nullptr, 16);
      m.end = std::stoull(range.substr(dash + 1), nullptr, 16);
      std::string perms, offset, device, inode;
      in >> perms >> offset >> device >> inode >> m.name;
      list.push_back(m);
    } else if (range == "THPeligible:" && !list.empty()) {
      in >> field;
      list.back().huge_page_eligible = field == "1";
    }
  }
  return list;
}

TEST(HeapPages, BlocksOfAFewMiBComeFromTheHeapMarkedForHugePages) {
  granbench::cli::use_huge_pages_for_the_heap();
  void* volatile block = std::malloc(std::size_t(4) << 20);  // (volatile: kept by the compiler)
  const auto at = reinterpret_cast<std::uintptr_t>(block);
  const auto list = mappings();
  bool in_heap = false, eligible = false;
  for (const Mapping& m : list) {
    if (m.name != "[heap]") continue;
    in_heap = in_heap || (at >= m.begin && at < m.end);
    eligible = eligible || m.huge_page_eligible;
  }
  std::free(block);
  EXPECT_TRUE(in_heap) << "a 4 MiB block was mapped on its own (the mmap threshold was not set)";

  std::ifstream policy("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(policy, modes);
  if (modes.find("[madvise]") == std::string::npos && modes.find("[always]") == std::string::npos)
    GTEST_SKIP() << "this kernel gives no huge pages on request (" << modes << ")";
  EXPECT_TRUE(eligible) << "no part of the heap is marked for huge pages";
}

// The blocks made after the call come from the marked part of the heap, not from the part
// below its first 2 MiB boundary (which cannot be a huge page). A block of 1 MiB: larger than
// any block the test program freed before, so it is cut from the heap's free top.
TEST(HeapPages, LaterBlocksComeFromTheMarkedPartOfTheHeap) {
  granbench::cli::use_huge_pages_for_the_heap();
  std::ifstream policy("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(policy, modes);
  if (modes.find("[madvise]") == std::string::npos && modes.find("[always]") == std::string::npos)
    GTEST_SKIP() << "this kernel gives no huge pages on request (" << modes << ")";
  void* volatile block = std::malloc(std::size_t(1) << 20);
  const auto at = reinterpret_cast<std::uintptr_t>(block);
  bool marked = false;
  for (const Mapping& m : mappings())
    marked = marked || (m.name == "[heap]" && m.huge_page_eligible && at >= m.begin && at < m.end);
  std::free(block);
  EXPECT_TRUE(marked) << "a block made after the call lies in the heap's unmarked start";
}

}  // namespace

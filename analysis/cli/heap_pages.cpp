// The heap on huge pages; see heap_pages.hpp.
#include "analysis/cli/heap_pages.hpp"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

namespace granbench::cli {

void use_huge_pages_for_the_heap() {
  constexpr std::size_t kHugePage = std::size_t(2) << 20;
  constexpr int kStep = 32 << 20;  // heap growth, largest block from the heap (bytes)
  mallopt(M_MMAP_THRESHOLD, kStep);
  mallopt(M_TRIM_THRESHOLD, 2 * kStep);
  mallopt(M_TOP_PAD, kStep);
  // Grow the heap now (a block larger than what is left of it, freed at once: it stays in the
  // heap), then mark the new range, in whole huge pages, for the kernel. (volatile: the compiler
  // may drop a malloc whose block is only freed)
  const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
  void* volatile block = std::malloc(kHugePage);
  const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::free(block);
  const std::uintptr_t begin = (before + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t end = after & ~(kHugePage - 1);
  // (a kernel without transparent huge pages refuses: the heap then stays on 4 KiB pages)
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

}  // namespace granbench::cli

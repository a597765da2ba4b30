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
  if (end <= begin || madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE) != 0)
    return;
  // The heap's free top starts below `begin`, in the part of the heap that cannot be a huge
  // page (the heap itself does not start on a 2 MiB boundary). Blocks are cut from the start of
  // the free top, so without the spacer below the next blocks (the 2D theory's pencils, the
  // solver's arrays) fell there, on 4 KiB pages: the Gerris comparison's run took 807 page
  // faults, and 386 with the spacer when the kernel had a huge page to give
  // (docs/performance.md, forty-seventh session). The spacer is one block from the start of the
  // free top up to `begin`, kept for the life of the process and never touched (it uses no
  // memory); every later block from the top lies in the marked range.
  // glibc's mallinfo2 gives the size of the main heap's free top, which ends at the break.
  // (a top that starts just below `begin` is moved to the next huge page: the spacer needs room
  // for its header)
  const std::uintptr_t top = reinterpret_cast<std::uintptr_t>(sbrk(0)) - mallinfo2().keepcost;
  constexpr std::uintptr_t kHeader = 2 * sizeof(std::size_t);  // glibc's block header
  const std::uintptr_t first = begin >= top + 2 * kHeader ? begin : begin + kHugePage;
  if (first >= end) return;
  void* spacer = std::malloc(first - top - kHeader);  // a block of first - top bytes
  // (a block that did not come from the top, which glibc does not do here, is given back)
  if (reinterpret_cast<std::uintptr_t>(spacer) != top + kHeader) std::free(spacer);
}

}  // namespace granbench::cli

// The command's heap on 2 MiB pages (transparent huge pages) where the kernel allows them on
// request (/sys/kernel/mm/transparent_hugepage/enabled: "madvise" or "always").
//
// Why: on the virtual machines we run on, the first touch of each 4 KiB page costs about 11 us
// (a page fault through the hypervisor), against 0.3 us per 4 KiB inside a 2 MiB page. A
// Gerris-sized 2D run touches some 1 500 fresh pages in its first step (HDF5's caches, the seed's
// dense pencils, the solver's arrays): 8 ms of its 230 (docs/performance.md, forty-fifth session).
#pragma once

namespace granbench::cli {

// Call once at the start of main, before the heap is in use for large blocks:
//   - blocks up to 32 MiB come from the heap (not from mmap) and a freed block stays in the
//     process for the next one (mallopt), so a block that is freed and made again each step is
//     not faulted in again;
//   - the heap grows by 32 MiB at a time, and that range is marked for huge pages (madvise);
//   - the blocks made after the call start in the marked range: the part of the heap below its
//     first 2 MiB boundary is filled by one block that is never used.
// Results do not change: only where the memory comes from.
void use_huge_pages_for_the_heap();

}  // namespace granbench::cli

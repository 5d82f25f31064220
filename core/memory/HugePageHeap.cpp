// SPDX-License-Identifier: GPL-3.0-or-later
#include "HugePageHeap.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

namespace rs::memory {

// A check of a large project allocates its syntax tree in small pieces and
// touches every page of it once: on a virtual machine the page faults were a
// third of the time. The heap is grown once by a reserve far beyond any
// project (address space only: a page costs memory when it is touched) and
// that range is marked for transparent huge pages, 512 times fewer faults.
// glibc does the same when told to by GLIBC_TUNABLES=glibc.malloc.hugetlb=1,
// which a program cannot set for itself once started.
void backTheHeapWithHugePages() {
#ifdef MADV_HUGEPAGE
    constexpr std::size_t kReserve = std::size_t{1} << 30;
    constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
    // Every block from that range: one arena for all threads (the IDE
    // compiles on a worker; another arena would be a mapping of its own), no
    // trimming, and large blocks from it too (a separate mapping for each
    // would fault page by page again).
    mallopt(M_ARENA_MAX, 1);
    mallopt(M_TRIM_THRESHOLD, static_cast<int>(kReserve));
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    mallopt(M_TOP_PAD, static_cast<int>(kReserve));
    const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
    // Beyond the free top, so the heap grows by the reserve; volatile, as a
    // block never used may be left unallocated.
    void* volatile grow = std::malloc(256 << 10);
    const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
    std::free(grow);
    mallopt(M_TOP_PAD, 128 * 1024); // mallopt(3)'s default again
    const std::uintptr_t start = (before + kHugePage - 1) & ~(kHugePage - 1);
    if (after > start)
        madvise(reinterpret_cast<void*>(start), after - start, MADV_HUGEPAGE);
#endif
}

} // namespace rs::memory

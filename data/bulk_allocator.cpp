#include "data/bulk_allocator.h"

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#endif

namespace ensil::data {
namespace {
constexpr std::size_t kBulkThreshold = std::size_t{1} << 20;

#if defined(__linux__)
// Transparent huge pages are 2 MiB on x86-64 and on most arm64 kernels.
constexpr std::size_t kHugePage = std::size_t{2} << 20;

std::size_t pageSize() {
    static const auto size = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    return size;
}

std::size_t roundUp(std::size_t bytes, std::size_t to) { return (bytes + to - 1) / to * to; }

// Maps `bytes` starting on a 2 MiB boundary, so that the kernel can back every whole 2 MiB of it
// with one huge page. Over-maps by 2 MiB and gives back the ends.
char* mapAlignedToHugePages(std::size_t length) {
    void* p = mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                   -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    char* const start = static_cast<char*>(p);
    char* const aligned =
        reinterpret_cast<char*>(roundUp(reinterpret_cast<std::uintptr_t>(start), kHugePage));
    if (aligned > start) munmap(start, static_cast<std::size_t>(aligned - start));
    const std::size_t tail =
        static_cast<std::size_t>(start + length + kHugePage - aligned) - length;
    if (tail > 0) munmap(aligned + length, tail);
    return aligned;
}
#endif
}  // namespace

void* allocateBulk(std::size_t bytes) {
#if defined(__linux__)
    if (bytes >= kBulkThreshold) {
        const std::size_t length = roundUp(bytes, pageSize());
        char* const block = mapAlignedToHugePages(length);
        // Huge pages where the kernel has them (transparent huge pages in "madvise" mode, as
        // on Debian): on virtual machines every 4 KiB page costs a fault of several
        // microseconds at its first use from user space, even when mapped in advance, and
        // again when the kernel first copies into it: reading a 100 MB time step took 130 ms
        // for the faults, and the first pass over it another 130 ms (ensil_time_benchmark).
        // With 2 MiB pages there is one fault where there were 512.
        madvise(block, length, MADV_HUGEPAGE);
        // All pages mapped in one call (MAP_POPULATE's effect, after the advice above, which
        // MAP_POPULATE would come before). Older kernels lack it: then each page is touched.
        if (madvise(block, length, MADV_POPULATE_WRITE) != 0) {
            for (std::size_t at = 0; at < length; at += pageSize()) block[at] = 0;
        }
        return block;
    }
#endif
    return ::operator new(bytes);
}

void releaseBulk(void* pointer, std::size_t bytes) {
    if (pointer == nullptr) return;
#if defined(__linux__)
    if (bytes >= kBulkThreshold) {
        munmap(pointer, roundUp(bytes, pageSize()));
        return;
    }
#endif
    ::operator delete(pointer);
}

}  // namespace ensil::data

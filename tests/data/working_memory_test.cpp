#include "data/working_memory.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstddef>
#include <new>

namespace {

[[maybe_unused]] long minorFaults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

constexpr std::size_t kPage = 4096;

// A block like a member's working buffers, every page written, then freed.
[[maybe_unused]] void touchAndFree(std::size_t bytes) {
    auto* block = static_cast<volatile char*>(::operator new(bytes));
    for (std::size_t i = 0; i < bytes; i += kPage) block[i] = 1;
    ::operator delete(const_cast<char*>(block));
}

}  // namespace

TEST(WorkingMemory, ABlockFreedIsUsedAgainWithoutFreshPages) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer's allocator stands in for glibc's, whose settings these are";
#else
    ASSERT_TRUE(ensil::data::keepWorkingMemoryForReuse());
    // 8 MiB, 2048 pages: by default glibc maps it on its own and unmaps it when freed, and the
    // next block of that size grows the heap with fresh pages.
    constexpr std::size_t kBytes = std::size_t{8} << 20;
    touchAndFree(kBytes);
    const long before = minorFaults();
    touchAndFree(kBytes);
    const long faults = minorFaults() - before;
    EXPECT_LT(faults, static_cast<long>(kBytes / kPage / 8))
        << "the second block of " << kBytes << " bytes took " << faults << " page faults";
#endif
}

// The calls that differ between Linux, macOS and Windows, in one place: every other file of the
// product is portable C++, Qt and the data libraries (packaging/check-platform-calls.py fails
// on such a call anywhere else). The Linux branches are what CI builds and tests; the macOS and
// Windows branches are written from those systems' documentation and are compiled by the CI
// workflows in .github/workflows, which no machine here has run. Any thread unless said.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace ensil::data {

// What tells whether a file may have changed since it was last read: its device and file
// number, size, and modification and status-change times in nanoseconds since 1970 (Windows
// has no status-change time: its last write stands in for both).
struct FileStamp {
    std::uint64_t device = 0;
    std::uint64_t file = 0;
    std::uint64_t size = 0;
    std::int64_t modifiedNs = 0;
    std::int64_t changedNs = 0;
    bool operator==(const FileStamp&) const = default;
};
std::optional<FileStamp> fileStamp(const std::string& path);

// The physical memory available to a new allocation without swapping, in bytes (Linux:
// MemAvailable; macOS: free and inactive pages; Windows: the available physical memory); 0 when
// the system does not say.
std::size_t availableMemoryBytes();

// Whether standard error is a terminal (a progress line may redraw itself there).
bool standardErrorIsTerminal();

// This process's resident memory now and its peak, in bytes, where the system tells them.
std::optional<std::size_t> residentMemoryBytes();
std::optional<std::size_t> peakResidentMemoryBytes();
// Starts the peak afresh from the resident memory now (Linux only: elsewhere false, and the
// peak is the process's since it started).
bool resetPeakResidentMemory();

// glibc's allocator: blocks from `mappedAbove` bytes get their own mapping, and up to `keptFree`
// bytes freed at the heap's top are kept for reuse (data/working_memory.h says why). Setting
// either turns off glibc's sliding threshold. False where the C library is not glibc.
bool setAllocatorThresholds(std::size_t mappedAbove, std::size_t keptFree);

// Lowers the calling thread's scheduling priority to `niceness` (Unix nice, 0 to 19), never
// raising it; false where it cannot (macOS keeps the thread as it is).
bool lowerThisThreadPriority(int niceness);

// `bytes` (a multiple of the page size) of zeroed memory on 2 MiB boundaries, advised to the
// kernel as huge pages and mapped in at once (Linux: mapsHugePages()); nullptr elsewhere, where
// the caller uses the ordinary allocator. Throws std::bad_alloc when the mapping fails.
constexpr bool mapsHugePages() {
#if defined(__linux__)
    return true;
#else
    return false;
#endif
}
void* mapHugePages(std::size_t bytes);
void unmapHugePages(void* block, std::size_t bytes);
std::size_t pageSize();

// Call before the Q*Application exists. On Linux with XDG_RUNTIME_DIR unset or empty (containers,
// CI, cron, a batch node, sudo), Qt picks a folder itself and says so on stderr at every start;
// this makes <temp>/ensil-runtime-<uid> (mode 0700) and sets XDG_RUNTIME_DIR to it instead. A
// folder of that name that another user owns, or that others may enter, is not used (Qt then
// warns as before). Returns the folder set, or nothing when nothing was changed (always on
// macOS and Windows, where Qt uses no such folder). Main thread.
std::optional<std::string> ensurePrivateRuntimeDirectory();

}  // namespace ensil::data

#include "data/platform.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <system_error>

#if defined(_WIN32)
#define NOMINMAX
#include <io.h>
#include <psapi.h>
#include <windows.h>
#else
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#endif
#if defined(__linux__)
#include <sys/syscall.h>
#endif
#if defined(__APPLE__)
#include <mach/mach.h>
#endif
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace ensil::data {
namespace {

#if !defined(_WIN32)
std::int64_t nanoseconds(const timespec& t) {
    return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}
#endif

#if defined(__linux__)
// A "Key: 1234 kB" line of a /proc file, in bytes.
std::optional<std::size_t> procBytes(const char* file, const std::string& key) {
    std::ifstream in(file);
    std::string name;
    while (in >> name) {
        if (name == key + ":") {
            std::size_t kib = 0;
            if (in >> kib) return kib * 1024;
            return std::nullopt;
        }
        in.ignore(1 << 12, '\n');
    }
    return std::nullopt;
}
#endif

#if defined(_WIN32)
// FILETIME counts 100 ns from 1601; in nanoseconds from 1970, as timespec_get gives the time.
std::int64_t nanoseconds(const FILETIME& t) {
    constexpr std::int64_t kFrom1601To1970 = 116'444'736'000'000'000;  // in 100 ns
    return (((static_cast<std::int64_t>(t.dwHighDateTime) << 32) | t.dwLowDateTime) -
            kFrom1601To1970) *
           100;
}
#endif

}  // namespace

std::optional<FileStamp> fileStamp(const std::string& path) {
#if defined(_WIN32)
    const std::wstring wide = std::filesystem::path(path).wstring();
    HANDLE file = CreateFileW(wide.c_str(), FILE_READ_ATTRIBUTES,
                              FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr,
                              OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr);
    if (file == INVALID_HANDLE_VALUE) return std::nullopt;
    BY_HANDLE_FILE_INFORMATION info{};
    const bool ok = GetFileInformationByHandle(file, &info) != 0;
    CloseHandle(file);
    if (!ok) return std::nullopt;
    const std::int64_t written = nanoseconds(info.ftLastWriteTime);
    return FileStamp{info.dwVolumeSerialNumber,
                     (static_cast<std::uint64_t>(info.nFileIndexHigh) << 32) | info.nFileIndexLow,
                     (static_cast<std::uint64_t>(info.nFileSizeHigh) << 32) | info.nFileSizeLow,
                     written, written};
#else
    struct stat s {};
    if (::stat(path.c_str(), &s) != 0) return std::nullopt;
#if defined(__APPLE__)
    const timespec modified = s.st_mtimespec, changed = s.st_ctimespec;
#else
    const timespec modified = s.st_mtim, changed = s.st_ctim;
#endif
    return FileStamp{static_cast<std::uint64_t>(s.st_dev), static_cast<std::uint64_t>(s.st_ino),
                     static_cast<std::uint64_t>(s.st_size), nanoseconds(modified),
                     nanoseconds(changed)};
#endif
}

std::size_t availableMemoryBytes() {
#if defined(_WIN32)
    MEMORYSTATUSEX status{};
    status.dwLength = sizeof status;
    return GlobalMemoryStatusEx(&status) != 0 ? static_cast<std::size_t>(status.ullAvailPhys) : 0;
#elif defined(__APPLE__)
    vm_statistics64_data_t vm{};
    mach_msg_type_number_t count = HOST_VM_INFO64_COUNT;
    if (host_statistics64(mach_host_self(), HOST_VM_INFO64, reinterpret_cast<host_info64_t>(&vm),
                          &count) != KERN_SUCCESS) {
        return 0;
    }
    return static_cast<std::size_t>(vm.free_count + vm.inactive_count) *
           static_cast<std::size_t>(vm_page_size);
#else
    if (const auto available = procBytes("/proc/meminfo", "MemAvailable")) return *available;
    const long pages = sysconf(_SC_AVPHYS_PAGES);
    const long size = sysconf(_SC_PAGESIZE);
    return pages > 0 && size > 0 ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(size)
                                 : 0;
#endif
}

bool standardErrorIsTerminal() {
#if defined(_WIN32)
    return _isatty(_fileno(stderr)) != 0;
#else
    return ::isatty(STDERR_FILENO) == 1;
#endif
}

std::optional<std::size_t> residentMemoryBytes() {
#if defined(_WIN32)
    PROCESS_MEMORY_COUNTERS counters{};
    if (GetProcessMemoryInfo(GetCurrentProcess(), &counters, sizeof counters) == 0) return {};
    return static_cast<std::size_t>(counters.WorkingSetSize);
#elif defined(__APPLE__)
    mach_task_basic_info_data_t info{};
    mach_msg_type_number_t count = MACH_TASK_BASIC_INFO_COUNT;
    if (task_info(mach_task_self(), MACH_TASK_BASIC_INFO, reinterpret_cast<task_info_t>(&info),
                  &count) != KERN_SUCCESS) {
        return std::nullopt;
    }
    return static_cast<std::size_t>(info.resident_size);
#else
    return procBytes("/proc/self/status", "VmRSS");
#endif
}

std::optional<std::size_t> peakResidentMemoryBytes() {
#if defined(_WIN32)
    PROCESS_MEMORY_COUNTERS counters{};
    if (GetProcessMemoryInfo(GetCurrentProcess(), &counters, sizeof counters) == 0) return {};
    return static_cast<std::size_t>(counters.PeakWorkingSetSize);
#elif defined(__APPLE__)
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return std::nullopt;
    return static_cast<std::size_t>(usage.ru_maxrss);  // bytes on macOS
#else
    return procBytes("/proc/self/status", "VmHWM");
#endif
}

bool resetPeakResidentMemory() {
#if defined(__linux__)
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5\n";
    clear.flush();
    return clear.good();
#else
    return false;
#endif
}

bool setAllocatorThresholds(std::size_t mappedAbove, std::size_t keptFree) {
#if defined(__GLIBC__)
    // Setting either disables glibc's sliding threshold, which would otherwise raise the first
    // back to 32 MiB only after such a block has been freed once, and lower the second with it.
    return mallopt(M_MMAP_THRESHOLD, static_cast<int>(mappedAbove)) == 1 &&
           mallopt(M_TRIM_THRESHOLD, static_cast<int>(keptFree)) == 1;
#else
    (void)mappedAbove;
    (void)keptFree;
    return false;
#endif
}

bool lowerThisThreadPriority(int niceness) {
#if defined(__linux__)
    // On Linux, PRIO_PROCESS with a thread id sets that thread's nice value alone.
    const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
    errno = 0;
    const int current = ::getpriority(PRIO_PROCESS, tid);
    if (errno != 0) return false;
    if (current >= niceness) return true;
    return ::setpriority(PRIO_PROCESS, tid, niceness) == 0;
#elif defined(_WIN32)
    (void)niceness;
    return SetThreadPriority(GetCurrentThread(), THREAD_PRIORITY_BELOW_NORMAL) != 0;
#else
    (void)niceness;
    return false;
#endif
}

std::size_t pageSize() {
#if defined(_WIN32)
    SYSTEM_INFO info{};
    GetSystemInfo(&info);
    return info.dwPageSize;
#else
    static const auto size = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    return size;
#endif
}

void* mapHugePages(std::size_t bytes) {
#if defined(__linux__)
    // Transparent huge pages are 2 MiB on x86-64 and on most arm64 kernels. Over-maps by 2 MiB
    // and gives back the ends, so that every whole 2 MiB of the block can be one huge page.
    constexpr std::size_t kHugePage = std::size_t{2} << 20;
    void* p = mmap(nullptr, bytes + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                   -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    char* const start = static_cast<char*>(p);
    const auto address = reinterpret_cast<std::uintptr_t>(start);
    char* const aligned = start + ((kHugePage - address % kHugePage) % kHugePage);
    if (aligned > start) munmap(start, static_cast<std::size_t>(aligned - start));
    const std::size_t tail = static_cast<std::size_t>(start + bytes + kHugePage - aligned) - bytes;
    if (tail > 0) munmap(aligned + bytes, tail);
    // Huge pages where the kernel has them (transparent huge pages in "madvise" mode, as on
    // Debian): on virtual machines every 4 KiB page costs a fault of several microseconds at
    // its first use from user space, even when mapped in advance, and again when the kernel
    // first copies into it: reading a 100 MB time step took 130 ms for the faults, and the
    // first pass over it another 130 ms (ensil_time_benchmark). With 2 MiB pages there is one
    // fault where there were 512.
    madvise(aligned, bytes, MADV_HUGEPAGE);
    // All pages mapped in one call (MAP_POPULATE's effect, after the advice above, which
    // MAP_POPULATE would come before). Older kernels lack it: then each page is touched.
    if (madvise(aligned, bytes, MADV_POPULATE_WRITE) != 0) {
        for (std::size_t at = 0; at < bytes; at += pageSize()) aligned[at] = 0;
    }
    return aligned;
#else
    (void)bytes;
    return nullptr;
#endif
}

void unmapHugePages(void* block, std::size_t bytes) {
#if defined(__linux__)
    munmap(block, bytes);
#else
    (void)block;
    (void)bytes;
#endif
}

std::optional<std::string> ensurePrivateRuntimeDirectory() {
#if defined(__linux__)
    const char* given = std::getenv("XDG_RUNTIME_DIR");
    if (given != nullptr && *given != '\0') return std::nullopt;
    std::error_code error;
    const std::filesystem::path temp = std::filesystem::temp_directory_path(error);
    if (error) return std::nullopt;
    const std::filesystem::path dir = temp / ("ensil-runtime-" + std::to_string(::getuid()));
    // mkdir with 0700 where it is missing; where it exists, it must be ours and closed to others
    // (a folder another user made in /tmp under this name must not receive our sockets).
    if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST) return std::nullopt;
    struct stat info {};
    if (::lstat(dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode) || info.st_uid != ::getuid() ||
        (info.st_mode & 077) != 0) {
        return std::nullopt;
    }
    ::setenv("XDG_RUNTIME_DIR", dir.c_str(), 1);
    return dir.string();
#else
    return std::nullopt;  // Qt uses no XDG_RUNTIME_DIR on macOS and Windows
#endif
}

}  // namespace ensil::data

#include "data/bulk_allocator.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace ensil::data {
namespace {
constexpr std::size_t kBulkThreshold = std::size_t{1} << 20;
}

void* allocateBulk(std::size_t bytes) {
#if defined(__linux__)
    if (bytes >= kBulkThreshold) {
        void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE,
                       MAP_PRIVATE | MAP_ANONYMOUS | MAP_POPULATE, -1, 0);
        if (p == MAP_FAILED) throw std::bad_alloc();
        return p;
    }
#endif
    return ::operator new(bytes);
}

void releaseBulk(void* pointer, std::size_t bytes) {
    if (pointer == nullptr) return;
#if defined(__linux__)
    if (bytes >= kBulkThreshold) {
        munmap(pointer, bytes);
        return;
    }
#endif
    ::operator delete(pointer);
}

}  // namespace ensil::data

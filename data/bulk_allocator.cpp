#include "data/bulk_allocator.h"

#include "data/platform.h"

namespace ensil::data {
namespace {
// Blocks from 1 MiB up are mapped as huge pages where the system has them (data/platform.h).
constexpr std::size_t kBulkThreshold = std::size_t{1} << 20;

std::size_t roundUp(std::size_t bytes, std::size_t to) { return (bytes + to - 1) / to * to; }
}  // namespace

void* allocateBulk(std::size_t bytes) {
    if (bytes >= kBulkThreshold) {
        if (void* block = mapHugePages(roundUp(bytes, pageSize()))) return block;
    }
    return ::operator new(bytes);
}

void releaseBulk(void* pointer, std::size_t bytes) {
    if (pointer == nullptr) return;
    if (bytes >= kBulkThreshold && mapsHugePages()) {
        unmapHugePages(pointer, roundUp(bytes, pageSize()));
        return;
    }
    ::operator delete(pointer);
}

}  // namespace ensil::data

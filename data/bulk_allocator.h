// Allocator for the large value blocks of ensemble members and other grid-sized fields. Two
// things make loading fast:
//  - Blocks of 1 MiB and more are mapped on Linux starting on a 2 MiB boundary, advised for
//    transparent huge pages and mapped in one call (data/bulk_allocator.cpp says why: on
//    virtual machines each 4 KiB page costs a fault of several microseconds at its first use,
//    and reading a time step paid for 25,000 of them twice).
//  - Elements are default-initialised, not zeroed: readers overwrite every value anyway, and
//    zeroing 100 MB is another pass over memory.
// Stateless, thread-safe; other platforms fall back to operator new.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace ensil::data {

void* allocateBulk(std::size_t bytes);
void releaseBulk(void* pointer, std::size_t bytes);

template <typename T>
struct BulkAllocator {
    using value_type = T;

    BulkAllocator() = default;
    template <typename U>
    explicit BulkAllocator(const BulkAllocator<U>& /*unused*/) noexcept {}

    T* allocate(std::size_t n) { return static_cast<T*>(allocateBulk(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { releaseBulk(p, n * sizeof(T)); }

    // Default-initialise (no zeroing) when no value is given.
    template <typename U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    template <typename U>
    bool operator==(const BulkAllocator<U>& /*unused*/) const noexcept {
        return true;
    }
};

// The values of one member (or any grid-sized field): x fastest, NaN where missing.
using FieldValues = std::vector<float, BulkAllocator<float>>;

}  // namespace ensil::data

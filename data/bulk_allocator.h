// Allocator for the large value blocks of ensemble members. Two things make loading fast:
//  - Blocks of 1 MiB and more are mapped with MAP_POPULATE on Linux, which maps all pages in
//    one call. Touching fresh pages one by one costs a fault each; on virtual machines that is
//    ~10 us per 4 KiB page, 250 ms for a 100 MB ensemble, ten times the cost of reading it.
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

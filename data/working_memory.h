// The pipelines' working memory (meshoptimizer's tables, marching cubes' bit rows and output,
// the similarity's blocks) is allocated and freed again for every member, isovalue and time
// step. glibc gives each block of 128 KiB or more a mapping of its own and returns it to the
// system when freed, so the next member touches fresh pages, a fault each: about 10 us a page
// on a virtual machine (bulk_allocator.h). On the paper-sized demo that was half the
// decimation's time and half the marching cubes' (ensil_preprocess_benchmark,
// docs/benchmarks.md). keepWorkingMemoryForReuse() keeps blocks up to kMappedAbove in the heap
// and keeps up to kKeptFree of freed memory at each heap's top, so they are used again
// instead.
// Larger blocks (a 256^3 member's values, through bulk_allocator.h anyway) still get mappings
// of their own and go back to the system when freed.
//
// It sets a process-wide policy, so executables call it first thing in main (ensil and the
// benchmarks that time what ensil does); the Python module leaves its host's allocator alone.
// Elsewhere than glibc it does nothing.
#pragma once

#include <cstddef>

namespace ensil::data {

struct WorkingMemoryPolicy {
    // Blocks at least this large are mapped on their own (glibc's default starts at 128 KiB).
    static constexpr std::size_t kMappedAbove = std::size_t{32} << 20;
    // Free memory kept at the top of each heap before it is returned (glibc's default 128 KiB).
    static constexpr std::size_t kKeptFree = std::size_t{64} << 20;
};

// Returns whether the policy is in force (false where the C library has no such settings).
bool keepWorkingMemoryForReuse();

}  // namespace ensil::data

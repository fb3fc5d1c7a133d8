#include "data/working_memory.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace ensil::data {

bool keepWorkingMemoryForReuse() {
#if defined(__GLIBC__)
    // Setting either disables glibc's sliding threshold, which would otherwise raise the first
    // back to 32 MiB only after such a block has been freed once, and lower the second with it.
    return mallopt(M_MMAP_THRESHOLD, static_cast<int>(WorkingMemoryPolicy::kMappedAbove)) == 1 &&
           mallopt(M_TRIM_THRESHOLD, static_cast<int>(WorkingMemoryPolicy::kKeptFree)) == 1;
#else
    return false;
#endif
}

}  // namespace ensil::data

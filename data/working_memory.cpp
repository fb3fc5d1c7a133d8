#include "data/working_memory.h"

#include "data/platform.h"

namespace ensil::data {

bool keepWorkingMemoryForReuse() {
    return setAllocatorThresholds(WorkingMemoryPolicy::kMappedAbove,
                                  WorkingMemoryPolicy::kKeptFree);
}

}  // namespace ensil::data

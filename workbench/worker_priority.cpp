#include "workbench/worker_priority.h"

#include "data/platform.h"

namespace ensil::workbench {

bool lowerThisThreadPriority() { return data::lowerThisThreadPriority(kWorkerNice); }

}  // namespace ensil::workbench

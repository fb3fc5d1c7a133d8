#include "workbench/worker_priority.h"

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#endif

namespace ensil::workbench {

bool lowerThisThreadPriority() {
#if defined(__linux__)
    // On Linux, PRIO_PROCESS with a thread id sets that thread's nice value alone.
    const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
    errno = 0;
    const int current = ::getpriority(PRIO_PROCESS, tid);
    if (errno != 0) return false;
    if (current >= kWorkerNice) return true;
    return ::setpriority(PRIO_PROCESS, tid, kWorkerNice) == 0;
#else
    return false;
#endif
}

}  // namespace ensil::workbench

#include "workbench/worker_priority.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <QObject>
#include <QSignalSpy>
#include <QTest>
#include <thread>

#include "workbench/background_job.h"

using namespace ensil::workbench;

namespace {
int niceOfThisThread() {
    return ::getpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)));
}
}  // namespace

TEST(WorkerPriority, LowersOnlyTheCallingThreadAndThreadsItStarts) {
    const int mine = niceOfThisThread();
    int lowered = -100;
    int started = -100;
    std::thread worker([&] {
        EXPECT_TRUE(lowerThisThreadPriority());
        EXPECT_TRUE(lowerThisThreadPriority()) << "a second call is fine";
        lowered = niceOfThisThread();
        // How oneTBB's workers, started from a job's thread, get the job's priority.
        std::thread child([&] { started = niceOfThisThread(); });
        child.join();
    });
    worker.join();
    EXPECT_EQ(lowered, std::max(mine, kWorkerNice));
    EXPECT_EQ(started, lowered);
    EXPECT_EQ(niceOfThisThread(), mine) << "the calling (GUI) thread keeps its priority";
}

TEST(WorkerPriority, BackgroundJobsRunBelowTheGuiThread) {
    QObject context;
    BackgroundJob<int> job(&context);
    int niceInJob = -100;
    bool done = false;
    job.start(
        [](const std::stop_token&, const ensil::data::Progress&) { return niceOfThisThread(); },
        [&](int n) {
            niceInJob = n;
            done = true;
        },
        [&](const std::exception_ptr&, bool) { done = true; });
    QTRY_VERIFY_WITH_TIMEOUT(done, 10000);
    EXPECT_EQ(niceInJob, std::max(niceOfThisThread(), kWorkerNice));
}

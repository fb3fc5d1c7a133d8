// The one job path: a job abandoned with its owner (a closed dialog's probe) does not hold the
// GUI thread until it returns; one that waits does.
#include "workbench/background_job.h"

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QObject>
#include <atomic>
#include <chrono>
#include <memory>
#include <semaphore>
#include <string>

#include "data/error.h"

using namespace ensil::workbench;

namespace {
// A job that runs until released (or 30 s), then says it returned.
struct HeldJob {
    std::shared_ptr<std::binary_semaphore> release = std::make_shared<std::binary_semaphore>(0);
    std::shared_ptr<std::atomic<bool>> returned = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<std::binary_semaphore> started = std::make_shared<std::binary_semaphore>(0);

    void startOn(BackgroundJob<int>& job) {
        job.start(
            [release = release, returned = returned, started = started](
                const std::stop_token&, const ensil::data::Progress&) {
                started->release();
                (void)release->try_acquire_for(std::chrono::seconds(30));
                returned->store(true);
                return 1;
            },
            [](int) {}, [](const std::exception_ptr&, bool) {});
        started->acquire();
    }
};
}  // namespace

TEST(BackgroundJob, AnAbandonedJobDoesNotHoldItsOwnersDestruction) {
    HeldJob held;
    {
        QObject owner;
        BackgroundJob<int> job(&owner, BackgroundJob<int>::WhenDestroyed::Abandon);
        held.startOn(job);
    }
    EXPECT_FALSE(held.returned->load()) << "destroyed while its work still runs";
    held.release->release();
}

TEST(BackgroundJob, AJobThatWaitsHasReturnedWhenItsOwnerIsGone) {
    HeldJob held;
    {
        QObject owner;
        BackgroundJob<int> job(&owner);
        held.startOn(job);
        held.release->release();
    }
    EXPECT_TRUE(held.returned->load());
}

TEST(BackgroundJob, AFailureHandsOnTheJobsOwnException) {
    // QtConcurrent wraps an exception that is not a QException; the callback gets the job's own,
    // so a panel can say what went wrong rather than "std::exception".
    QObject owner;
    BackgroundJob<int> job(&owner);
    std::string said;
    bool failed = false;
    job.start(
        [](const std::stop_token&, const ensil::data::Progress&) -> int {
            throw ensil::data::Error(ensil::data::ErrorKind::InvalidArgument,
                                     "a level of 1000 hPa lies outside the data");
        },
        [](int) {},
        [&](const std::exception_ptr& error, bool cancelled) {
            failed = !cancelled;
            try {
                std::rethrow_exception(error);
            } catch (const ensil::data::Error& e) {
                said = e.what();
            } catch (...) {
                said = "another exception";
            }
        });
    job.wait();
    // The outcome comes through the event loop, as a queued signal.
    for (int i = 0; i < 1000 && !failed; ++i) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    }
    EXPECT_TRUE(failed);
    EXPECT_EQ(said, "a level of 1000 hPa lies outside the data");
}

#include "preprocessing/side_by_side.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <atomic>
#include <stdexcept>
#include <thread>

using namespace ensil;

TEST(SideBySide, APartThatThrowsDoesNotCutTheOthersInnerLoopsShort) {
    // The first part throws once the second is inside its parallel loop; that loop's first
    // item then waits to see whether oneTBB cancels the group (as a bare parallel_invoke does,
    // skipping the items not yet begun). Side by side, nothing is cancelled: every item runs.
    std::atomic<bool> inside{false}, thrown{false};
    std::atomic<int> done{0};
    constexpr int kItems = 2000;
    const auto throwing = [&] {
        // Bounded, so that with a single worker (the parts then run one after the other) it
        // throws anyway, and the loop still has to run all its items.
        for (int k = 0; k < 1000000 && !inside.load(); ++k) std::this_thread::yield();
        thrown = true;
        throw std::runtime_error("part one failed");
    };
    const auto looping = [&] {
        tbb::parallel_for(0, kItems, [&](int i) {
            if (i == 0) {
                inside = true;
                for (int k = 0; k < 1000000 && !thrown.load(); ++k) std::this_thread::yield();
                // Give a cancellation every chance to arrive (a bounded wait on its flag).
                for (int k = 0; k < 200000 && !tbb::is_current_task_group_canceling(); ++k) {
                    std::this_thread::yield();
                }
            }
            ++done;
        });
    };
    EXPECT_THROW(prep::runSideBySide(throwing, looping), std::runtime_error);
    EXPECT_EQ(done.load(), kItems);
}

TEST(SideBySide, RunsEveryPartAndRethrowsTheFirstFailureInPartOrder) {
    std::atomic<int> ran{0};
    try {
        prep::runSideBySide([&] { ++ran; }, [&] { ++ran, throw std::logic_error("second"); },
                            [&] { ++ran, throw std::runtime_error("third"); });
        FAIL() << "no exception";
    } catch (const std::logic_error& e) {
        EXPECT_STREQ(e.what(), "second");
    }
    EXPECT_EQ(ran.load(), 3);
    int sum = 0;
    prep::runSideBySide([&] { sum += 1; }, [] {});
    EXPECT_EQ(sum, 1);
}

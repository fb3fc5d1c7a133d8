#include "workbench/event_loop_stall_monitor.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QTest>
#include <QTimer>
#include <cstddef>

using namespace ensil::workbench;

namespace {
void blockFor(int ms) {
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms) {
    }
}
}  // namespace

TEST(EventLoopStallMonitor, ABlockedEventLoopShowsAsOneLongStall) {
    EventLoopStallMonitor monitor(5);
    const auto samplesReach = [&monitor](std::size_t count) {
        return QTest::qWaitFor([&] { return monitor.latenessMs().size() >= count; }, 60000);
    };
    monitor.start();
    ASSERT_TRUE(samplesReach(12)) << "samples before the stall";
    // The stall: a handler that keeps the event loop from running for 150 ms.
    bool blocked = false;
    QTimer::singleShot(0, &monitor, [&blocked] {
        blockFor(150);
        blocked = true;
    });
    ASSERT_TRUE(QTest::qWaitFor([&] { return blocked; }, 60000));
    // The next timeout measures the stall; short samples follow it.
    ASSERT_TRUE(samplesReach(monitor.latenessMs().size() + 12)) << "samples after the stall";
    monitor.stop();
    const StallSummary s = monitor.summary();
    // The timeouts before and after the handler are at least 150 ms apart: lateness is that
    // less the 5 ms interval. No upper bound: a loaded machine may keep the loop away longer.
    EXPECT_GE(s.longestMs, 140.0);
    EXPECT_GT(s.samples, 10u);
    // One long sample among many short ones: the median stays small.
    EXPECT_LT(s.medianMs, s.longestMs);
    EXPECT_EQ(s.samples, monitor.latenessMs().size());
}

TEST(EventLoopStallMonitor, StartForgetsEarlierSamples) {
    EventLoopStallMonitor monitor(5);
    monitor.start();
    EXPECT_TRUE(QTest::qWaitFor([&] { return !monitor.latenessMs().empty(); }, 60000));
    monitor.stop();
    EXPECT_GT(monitor.latenessMs().size(), 0u);
    monitor.start();
    monitor.stop();
    EXPECT_EQ(monitor.latenessMs().size(), 0u);
    EXPECT_EQ(monitor.summary().longestMs, 0.0);
}

TEST(Percentile, UsesTheNearestRank) {
    std::vector<double> samples;
    for (int i = 1; i <= 200; ++i) samples.push_back(i);
    EXPECT_EQ(percentile(samples, 99.0), 198.0);
    EXPECT_EQ(percentile(samples, 50.0), 100.0);
    EXPECT_EQ(percentile(samples, 100.0), 200.0);
    EXPECT_EQ(percentile({3.0}, 99.0), 3.0);
    EXPECT_EQ(percentile({}, 99.0), 0.0);
}

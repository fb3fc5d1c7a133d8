#include "app/event_loop_stall_monitor.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QTest>
#include <QTimer>

using namespace ensil::app;

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
    monitor.start();
    QTest::qWait(60);
    QTimer::singleShot(0, [] { blockFor(150); });
    QTest::qWait(100 + 150);
    monitor.stop();
    const StallSummary s = monitor.summary();
    EXPECT_GE(s.longestMs, 140.0);
    EXPECT_LT(s.longestMs, 1000.0);
    EXPECT_GT(s.samples, 10u);
    // One long sample among many short ones: the median stays small.
    EXPECT_LT(s.medianMs, s.longestMs);
    EXPECT_EQ(s.samples, monitor.latenessMs().size());
}

TEST(EventLoopStallMonitor, StartForgetsEarlierSamples) {
    EventLoopStallMonitor monitor(5);
    monitor.start();
    QTest::qWait(30);
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

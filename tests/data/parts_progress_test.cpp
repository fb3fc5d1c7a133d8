#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "data/job.h"

using namespace ensil;

TEST(WeightedPartsProgress, IsTheWeightedSumOfThePartsAndNeverGoesBack) {
    std::vector<double> seen;
    data::WeightedPartsProgress parts([&](double f) { seen.push_back(f); }, {3.0, 1.0});
    parts.part(0)(0.5);  // 3 * 0.5 / 4
    parts.part(1)(1.0);  // (1.5 + 1) / 4
    parts.part(0)(0.2);  // a part going back moves nothing
    parts.part(0)(1.0);
    ASSERT_EQ(seen.size(), 3u);
    EXPECT_DOUBLE_EQ(seen[0], 0.375);
    EXPECT_DOUBLE_EQ(seen[1], 0.625);
    EXPECT_DOUBLE_EQ(seen[2], 1.0);
}

TEST(WeightedPartsProgress, PartsOnManyThreadsReportAnIncreasingWholeThatEndsAtOne) {
    std::vector<double> seen;  // written under the progress object's lock
    data::WeightedPartsProgress parts([&](double f) { seen.push_back(f); }, {1.0, 2.0, 1.0, 4.0});
    std::vector<std::thread> threads;
    for (std::size_t p = 0; p < 4; ++p) {
        threads.emplace_back([&parts, p] {
            const data::Progress mine = parts.part(p);
            for (int i = 1; i <= 1000; ++i) mine(i / 1000.0);
        });
    }
    for (std::thread& t : threads) t.join();
    ASSERT_FALSE(seen.empty());
    for (std::size_t i = 1; i < seen.size(); ++i) ASSERT_LT(seen[i - 1], seen[i]) << i;
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);
}

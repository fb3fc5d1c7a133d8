#include "preprocessing/mean_member.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "data/error.h"
#include "fixtures.h"
#include "preprocessing/point_blocks.h"

using namespace ensil;

TEST(MeanMember, IsTheGridPointMean) {
    // f_m(i, j, k) = m + i + 10 j + 100 k; mean over m = 0..4 is 2 + i + 10 j + 100 k.
    const auto e = test::analyticEnsemble(5, 4, 3, 2, [](auto m, auto i, auto j, auto k) {
        return static_cast<float>(m + i + 10 * j + 100 * k);
    });
    const data::Member mean = prep::computeMeanMember(e);
    for (std::size_t k = 0; k < 2; ++k)
        for (std::size_t j = 0; j < 3; ++j)
            for (std::size_t i = 0; i < 4; ++i)
                EXPECT_FLOAT_EQ(mean.values[e.grid.index(i, j, k)],
                                static_cast<float>(2 + i + 10 * j + 100 * k));
    EXPECT_EQ(mean.name, "mean");
}

TEST(MeanMember, AveragesOverMembersThatHaveThePointAndKeepsCommonGaps) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    auto e = test::analyticEnsemble(3, 2, 2, 2, [](auto m, auto, auto, auto) {
        return static_cast<float>(3 * m);  // 0, 3, 6
    });
    e.members[2].values[1] = nan;                 // point 1: members 0 and 1 only -> 1.5
    for (auto& m : e.members) m.values[5] = nan;  // point 5: missing everywhere
    const data::Member mean = prep::computeMeanMember(e);
    EXPECT_FLOAT_EQ(mean.values[0], 3.0F);
    EXPECT_FLOAT_EQ(mean.values[1], 1.5F);
    EXPECT_TRUE(std::isnan(mean.values[5]));
}

TEST(MeanMember, CancelThrowsAndProgressIsMonotonic) {
    // 64 blocks of points (prep::kPointsPerBlock), summed on several threads.
    const std::size_t blocks = 64;
    const auto e =
        test::analyticEnsemble(3, 128, 128, blocks * prep::kPointsPerBlock / (128 * 128),
                               [](auto m, auto, auto, auto) { return static_cast<float>(m); });
    std::vector<double> fractions;
    const data::Member mean =
        prep::computeMeanMember(e, {}, [&](double f) { fractions.push_back(f); });
    EXPECT_EQ(fractions.size(), blocks) << "once per block of points";
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
    EXPECT_EQ(std::count(mean.values.begin(), mean.values.end(), 1.0F),
              static_cast<std::ptrdiff_t>(mean.values.size()))
        << "every block's points are the mean of 0, 1 and 2";

    std::stop_source stop;
    std::atomic<int> calls = 0;
    EXPECT_THROW(prep::computeMeanMember(e, stop.get_token(),
                                         [&](double) {
                                             if (++calls == 2) stop.request_stop();
                                         }),
                 data::Cancelled);
    // Blocks already begun on other threads finish; no block starts after the request.
    EXPECT_LT(calls, static_cast<int>(blocks) / 2) << "the step must stop soon after the request";
}

TEST(MeanMember, EmptyEnsembleIsATypedError) {
    data::Ensemble empty;
    EXPECT_THROW(prep::computeMeanMember(empty), data::Error);
}

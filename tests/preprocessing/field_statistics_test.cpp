#include "preprocessing/field_statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include "fixtures.h"

using namespace ensil;

TEST(FieldStatistics, RangeMeanAndMissingOfAnAnalyticField) {
    // Values 0..63 in member 0 and 64..127 in member 1: range [0, 127], mean 63.5.
    auto e = test::analyticEnsemble(2, 4, 4, 4, [](auto m, auto i, auto j, auto k) {
        return static_cast<float>(64 * m + i + 4 * j + 16 * k);
    });
    const prep::FieldStatistics s = prep::computeFieldStatistics(e, 8);
    EXPECT_FLOAT_EQ(s.minimum, 0.0F);
    EXPECT_FLOAT_EQ(s.maximum, 127.0F);
    EXPECT_DOUBLE_EQ(s.mean, 63.5);
    EXPECT_EQ(s.validCount, 128u);
    EXPECT_EQ(s.missingCount, 0u);
    // 128 evenly spread values in 8 equal bins: 16 each (the maximum falls in the last bin).
    ASSERT_EQ(s.histogram.size(), 8u);
    for (auto count : s.histogram) EXPECT_EQ(count, 16u);
}

TEST(FieldStatistics, NaNsAreCountedAsMissingAndIgnored) {
    auto e = test::analyticEnsemble(1, 2, 2, 2,
                                    [](auto, auto i, auto, auto) { return static_cast<float>(i); });
    e.members[0].values[0] = std::numeric_limits<float>::quiet_NaN();
    e.members[0].values[3] = std::numeric_limits<float>::quiet_NaN();
    const auto s = prep::computeFieldStatistics(e, 4);
    EXPECT_EQ(s.missingCount, 2u);
    EXPECT_EQ(s.validCount, 6u);
    EXPECT_EQ(std::accumulate(s.histogram.begin(), s.histogram.end(), std::uint64_t{0}), 6u);
}

TEST(FieldStatistics, ConstantFieldPutsEverythingInOneBin) {
    const auto e = test::analyticEnsemble(2, 3, 3, 3, [](auto, auto, auto, auto) { return 4.0F; });
    const auto s = prep::computeFieldStatistics(e, 10);
    EXPECT_FLOAT_EQ(s.minimum, 4.0F);
    EXPECT_FLOAT_EQ(s.maximum, 4.0F);
    EXPECT_EQ(s.histogram[0], 54u);
}

TEST(FieldStatistics, AllMissingGivesNoValidValues) {
    const auto e = test::analyticEnsemble(
        1, 2, 2, 2, [](auto, auto, auto, auto) { return std::numeric_limits<float>::quiet_NaN(); });
    const auto s = prep::computeFieldStatistics(e, 4);
    EXPECT_EQ(s.validCount, 0u);
    EXPECT_EQ(s.missingCount, 8u);
}

TEST(FieldStatistics, StopsWhenCancelled) {
    const auto e = test::analyticEnsemble(2, 2, 2, 2, [](auto, auto, auto, auto) { return 1.0F; });
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW(prep::computeFieldStatistics(e, 4, stop.get_token()), data::Cancelled);
}

TEST(FieldStatistics, MatchesAPlainLoopOverEveryValueWhateverTheirCount) {
    // 3 members of 7 x 5 x 3 = 105 values (not a multiple of the lanes the passes run in),
    // random with NaNs, the extremes in the last values of a member.
    std::uint64_t state = 12345;
    const auto next = [&] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<float>(state >> 40) / static_cast<float>(1 << 24);
    };
    auto e = test::analyticEnsemble(3, 7, 5, 3, [&](auto m, auto i, auto j, auto k) {
        if (i == 6 && j == 4 && k == 2) return m == 1 ? -50.0F : m == 2 ? 80.0F : 1.0F;
        const float u = next();
        return u < 0.1F ? std::numeric_limits<float>::quiet_NaN() : 100.0F * u - 20.0F;
    });
    const std::size_t bins = 16;
    const prep::FieldStatistics s = prep::computeFieldStatistics(e, bins);
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    double sum = 0.0;
    std::size_t valid = 0, missing = 0;
    for (const auto& member : e.members) {
        for (const float v : member.values) {
            if (std::isnan(v)) {
                ++missing;
                continue;
            }
            lo = std::min(lo, v);
            hi = std::max(hi, v);
            sum += v;
            ++valid;
        }
    }
    EXPECT_EQ(s.minimum, -50.0F);
    EXPECT_EQ(s.maximum, 80.0F);
    EXPECT_EQ(s.minimum, lo);
    EXPECT_EQ(s.maximum, hi);
    EXPECT_EQ(s.validCount, valid);
    EXPECT_EQ(s.missingCount, missing);
    EXPECT_NEAR(s.mean, sum / static_cast<double>(valid), 1e-12);
    std::vector<std::uint64_t> histogram(bins, 0);
    const double scale = static_cast<double>(bins) / (static_cast<double>(hi) - lo);
    for (const auto& member : e.members) {
        for (const float v : member.values) {
            if (std::isnan(v)) continue;
            const auto bin = static_cast<std::size_t>((static_cast<double>(v) - lo) * scale);
            ++histogram[std::min(bin, bins - 1)];
        }
    }
    EXPECT_EQ(s.histogram, histogram);
}

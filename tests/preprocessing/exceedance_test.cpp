// The exceedance probability alone (preprocessing/exceedance.h) is the ensemble statistics'
// P(f > c), to the bit, by the same rule for missing values.
#include "preprocessing/exceedance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "data/error.h"
#include "fixtures.h"
#include "preprocessing/ensemble_statistics.h"

using namespace ensil;

TEST(Exceedance, IsTheStatisticsExceedanceToTheBitWithMissingValues) {
    // 7 members over several blocks of points; NaN and infinities here and there, values equal
    // to the isovalue (not above it), and a row where no member has a value.
    std::mt19937_64 rng(9);
    std::uniform_int_distribution<int> pick(0, 24);
    const float c = 12.0F;
    const auto e = test::analyticEnsemble(7, 64, 48, 12, [&](auto, auto, auto j, auto) {
        if (j == 5) return std::numeric_limits<float>::quiet_NaN();
        const int p = pick(rng);
        if (p == 0) return std::numeric_limits<float>::quiet_NaN();
        if (p == 1) return std::numeric_limits<float>::infinity();
        if (p == 2) return -std::numeric_limits<float>::infinity();
        if (p == 3) return c;
        return static_cast<float>(p);
    });
    const data::FieldValues exceedance = prep::computeExceedance(e, c);
    const data::FieldValues expected = prep::computeEnsembleStatistics(e, c).exceedance;
    ASSERT_EQ(exceedance.size(), expected.size());
    std::size_t withoutValue = 0;
    for (std::size_t p = 0; p < exceedance.size(); ++p) {
        if (std::isnan(expected[p])) {
            EXPECT_TRUE(std::isnan(exceedance[p])) << "point " << p;
            ++withoutValue;
            continue;
        }
        ASSERT_EQ(exceedance[p], expected[p]) << "point " << p;
    }
    EXPECT_EQ(withoutValue, std::size_t{64} * 12);
}

TEST(Exceedance, IsTheShareOfMembersAboveTheIsovalue) {
    // Members 1 .. 4 everywhere, c = 2.5: two of four above.
    const auto e = test::analyticEnsemble(
        4, 3, 3, 2, [](auto m, auto, auto, auto) { return static_cast<float>(m + 1); });
    for (const float p : prep::computeExceedance(e, 2.5F)) EXPECT_EQ(p, 0.5F);
}

TEST(Exceedance, RefusesBadArgumentsAndStopsWhenAsked) {
    EXPECT_THROW((void)prep::computeExceedance(data::Ensemble{}, 1.0F), data::Error);
    const auto e = test::analyticEnsemble(
        2, 8, 8, 8, [](auto m, auto, auto, auto) { return static_cast<float>(m); });
    EXPECT_THROW((void)prep::computeExceedance(e, std::numeric_limits<float>::infinity()),
                 data::Error);
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW((void)prep::computeExceedance(e, 0.5F, stop.get_token()), data::Cancelled);
}

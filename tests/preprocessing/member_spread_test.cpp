// The members' spread alone (preprocessing/member_spread.h) is the ensemble statistics' sample
// standard deviation, by the same rule for missing values.
#include "preprocessing/member_spread.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "data/error.h"
#include "fixtures.h"
#include "preprocessing/ensemble_statistics.h"
#include "tests/support/special_values.h"

using namespace ensil;

namespace {

using test::kInf;
using test::kNaN;

}  // namespace

TEST(MemberSpread, IsTheStatisticsStandardDeviationWithMissingValuesAndLargeValues) {
    // Geopotential-like values (about 50000, spread about 30) over several blocks of points;
    // NaN and infinities missing here and there, member 0 missing on whole rows (the shift
    // falls back), and points where fewer than two members have a value.
    std::mt19937_64 rng(5);
    std::normal_distribution<float> value(50000.0F, 30.0F);
    std::uniform_int_distribution<int> pick(0, 19);
    const auto e = test::analyticEnsemble(9, 64, 48, 12, [&](auto m, auto, auto j, auto) {
        if (j == 3) return m < 8 ? kNaN : value(rng);  // one member only: no spread
        if (m == 0 && j % 5 == 0) return kNaN;
        const int p = pick(rng);
        return p == 0 ? kNaN : p == 1 ? (m % 2 == 0 ? kInf : -kInf) : value(rng);
    });
    const data::FieldValues spread = prep::computeMemberSpread(e);
    const prep::EnsembleStatistics statistics = prep::computeEnsembleStatistics(e, 0.0F);
    ASSERT_EQ(spread.size(), statistics.stddev.size());
    std::size_t withoutSpread = 0;
    for (std::size_t p = 0; p < spread.size(); ++p) {
        const float expected = statistics.stddev[p];
        if (std::isnan(expected)) {
            EXPECT_TRUE(std::isnan(spread[p])) << "point " << p;
            ++withoutSpread;
            continue;
        }
        ASSERT_NEAR(spread[p], expected, 1e-4F * expected) << "point " << p;
    }
    EXPECT_EQ(withoutSpread, std::size_t{64} * 12) << "the row where one member has values";
}

TEST(MemberSpread, ConstantMembersHaveTheirSampleStandardDeviation) {
    // Members 1, 2, 3 everywhere: s = 1 (sample, n - 1 = 2).
    const auto e = test::analyticEnsemble(
        3, 4, 3, 2, [](auto m, auto, auto, auto) { return static_cast<float>(m + 1); });
    for (const float s : prep::computeMemberSpread(e)) EXPECT_FLOAT_EQ(s, 1.0F);
}

TEST(MemberSpread, RefusesAnEnsembleWithoutMembersAndStopsWhenAsked) {
    EXPECT_THROW((void)prep::computeMemberSpread(data::Ensemble{}), data::Error);
    const auto e = test::analyticEnsemble(
        2, 8, 8, 8, [](auto m, auto, auto, auto) { return static_cast<float>(m); });
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW((void)prep::computeMemberSpread(e, stop.get_token()), data::Cancelled);
}

// The members' median at every point (preprocessing/member_median.h), whose isovalue surface
// is the context surface where half the members exceed the isovalue.
#include "preprocessing/member_median.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stop_token>
#include <vector>

#include "data/error.h"
#include "data/job.h"
#include "fixtures.h"
#include "preprocessing/exceedance.h"
#include "tests/support/special_values.h"

using namespace ensil;

namespace {
using test::kNaN;

// Members of seeded random values on a grid of more points than a block of work holds, so
// the blocks' and the gathers' borders are crossed.
data::Ensemble randomEnsemble(std::size_t members) {
    std::mt19937 random(members);
    std::uniform_real_distribution<float> value(-50.0F, 50.0F);
    return test::analyticEnsemble(members, 41, 29, 17,
                                  [&](auto, auto, auto, auto) { return value(random); });
}
}  // namespace

TEST(MemberMedian, TheMiddleValueOrTheMeanOfTheTwoMiddleOnesAtEveryPoint) {
    for (const std::size_t members : {1u, 2u, 6u, 7u}) {
        SCOPED_TRACE(members);
        const data::Ensemble e = randomEnsemble(members);
        const data::FieldValues median = prep::computeMemberMedian(e);
        ASSERT_EQ(median.size(), e.grid.pointCount());
        for (std::size_t p = 0; p < e.grid.pointCount(); ++p) {
            std::vector<float> sorted;
            for (const data::Member& m : e.members) sorted.push_back(m.values[p]);
            std::sort(sorted.begin(), sorted.end());
            const std::size_t half = members / 2;
            const float expected =
                members % 2 == 1 ? sorted[half] : 0.5F * sorted[half - 1] + 0.5F * sorted[half];
            ASSERT_EQ(median[p], expected) << "point " << p;
        }
    }
}

TEST(MemberMedian, AboveTheIsovalueWhereMoreThanHalfTheMembersExceedIt) {
    // The surface of the median at c is the surface where half the members exceed c: at every
    // point, P(f > c) above one half puts the median above c, below one half at or under it.
    for (const std::size_t members : {5u, 6u}) {
        const data::Ensemble e = randomEnsemble(members);
        const data::FieldValues median = prep::computeMemberMedian(e);
        for (const float c : {-20.0F, 0.0F, 13.0F}) {
            SCOPED_TRACE(testing::Message() << members << " members, c = " << c);
            const data::FieldValues p = prep::computeExceedance(e, c);
            std::size_t above = 0, below = 0;
            for (std::size_t i = 0; i < p.size(); ++i) {
                if (p[i] > 0.5F) {
                    ASSERT_GT(median[i], c) << "point " << i;
                    ++above;
                } else if (p[i] < 0.5F) {
                    ASSERT_LE(median[i], c) << "point " << i;
                    ++below;
                }
            }
            EXPECT_GT(above, 100u);
            EXPECT_GT(below, 100u);
        }
    }
}

TEST(MemberMedian, MissingValuesAreLeftOutAndAPointWithoutAnyIsMissing) {
    // Point 0: members 0 and 3 missing (NaN, infinite); point 1: every member missing; point 2:
    // member 1 missing. Member m is m + 1 elsewhere.
    const auto e = test::analyticEnsemble(4, 4, 2, 2, [](std::size_t m, std::size_t i, auto, auto) {
        if (i == 0 && m == 0) return kNaN;
        if (i == 0 && m == 3) return -std::numeric_limits<float>::infinity();
        if (i == 1) return kNaN;
        if (i == 2 && m == 1) return std::numeric_limits<float>::infinity();
        return static_cast<float>(m + 1);
    });
    const data::FieldValues median = prep::computeMemberMedian(e);
    EXPECT_EQ(median[0], 2.5F);  // of 2 and 3
    EXPECT_TRUE(std::isnan(median[1]));
    EXPECT_EQ(median[2], 3.0F);  // of 1, 3 and 4
    EXPECT_EQ(median[3], 2.5F);  // of 1, 2, 3 and 4
}

TEST(MemberMedian, TiesNegativeValuesAndZerosOfBothSigns) {
    // Four members; at point i their values are kValues[i].
    static constexpr float kValues[4][4] = {
        {5, 5, 5, 7}, {2, 5, 5, 7}, {-3, -1, -2, -8}, {-0.0F, 0.0F, 1, -1}};
    const auto e = test::analyticEnsemble(
        4, 4, 2, 2, [](std::size_t m, std::size_t i, auto, auto) { return kValues[i][m]; });
    const data::FieldValues median = prep::computeMemberMedian(e);
    EXPECT_EQ(median[0], 5.0F);  // the two middle values are equal
    EXPECT_EQ(median[1], 5.0F);
    EXPECT_EQ(median[2], -2.5F);  // of -3 and -2
    EXPECT_EQ(median[3], 0.0F);
}

TEST(MemberMedian, RefusesAnEnsembleWithoutMembersAndStopsWhenAsked) {
    EXPECT_THROW((void)prep::computeMemberMedian(data::Ensemble{}), data::Error);
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW((void)prep::computeMemberMedian(randomEnsemble(3), stop.get_token()),
                 data::Cancelled);
}

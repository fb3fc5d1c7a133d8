#include "preprocessing/column_maximum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fixtures.h"

using namespace ensil;

TEST(ColumnMaximum, PicksTheLargestValueOfEachColumn) {
    // f = i + j * k: the maximum over k in 0..3 is i + 3 j.
    const auto e = test::analyticEnsemble(
        1, 3, 2, 4, [](auto, auto i, auto j, auto k) { return static_cast<float>(i + j * k); });
    const auto map = prep::computeColumnMaximum(e.grid, e.members[0]);
    ASSERT_EQ(map.size(), 6u);
    for (std::size_t j = 0; j < 2; ++j)
        for (std::size_t i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(map[i + 3 * j], i + 3.0F * j);
}

TEST(ColumnMaximum, IgnoresMissingValuesAndKeepsAllMissingColumnsMissing) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    auto e = test::analyticEnsemble(1, 2, 2, 3,
                                    [](auto, auto, auto, auto k) { return static_cast<float>(k); });
    auto& v = e.members[0].values;
    v[e.grid.index(0, 0, 2)] = nan;  // column 0 without its top: maximum 1
    for (std::size_t k = 0; k < 3; ++k) v[e.grid.index(1, 0, k)] = nan;
    const auto map = prep::computeColumnMaximum(e.grid, e.members[0]);
    EXPECT_FLOAT_EQ(map[0], 1.0F);
    EXPECT_TRUE(std::isnan(map[1]));
}

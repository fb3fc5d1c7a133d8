#include "preprocessing/ensemble_statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "data/error.h"
#include "fixtures.h"
#include "tests/support/special_values.h"

using namespace ensil;

namespace {

using test::kInf;
using test::kNaN;

// Members given as tables of values in grid order (x fastest).
data::Ensemble tableEnsemble(std::size_t nx, std::size_t ny, std::size_t nz,
                             const std::vector<std::vector<float>>& values) {
    return test::analyticEnsemble(values.size(), nx, ny, nz, [&](auto m, auto i, auto j, auto k) {
        return values[m][i + nx * (j + ny * k)];
    });
}

// Three members on a 2 x 2 x 2 grid (points 0..7), c = 2; every case worked out by hand below.
//   point:   0    1    2    3     4  5   6   7
//   m0:      1    2    NaN  NaN   3  0  10   4
//   m1:      2    NaN  NaN  +inf  3  1  20   2
//   m2:      6    4    5    -inf  3  2  30   0
data::Ensemble threeMembers() {
    return tableEnsemble(2, 2, 2,
                         {{1, 2, kNaN, kNaN, 3, 0, 10, 4},
                          {2, kNaN, kNaN, kInf, 3, 1, 20, 2},
                          {6, 4, 5, -kInf, 3, 2, 30, 0}});
}

// One expected point: NaN in the expectation means "must be NaN".
struct Expected {
    float count, mean, stddev, minimum, maximum, range, exceedance;
};

void expectFloat(float actual, float expected, const std::string& what) {
    if (std::isnan(expected)) {
        EXPECT_TRUE(std::isnan(actual)) << what << " = " << actual << ", expected NaN";
    } else {
        EXPECT_NEAR(actual, expected, 1e-6F * std::max(1.0F, std::abs(expected))) << what;
    }
}

void expectPoint(const prep::EnsembleStatistics& s, std::size_t p, const Expected& e) {
    const std::string at = " at point " + std::to_string(p);
    expectFloat(s.count[p], e.count, "count" + at);
    expectFloat(s.mean[p], e.mean, "mean" + at);
    expectFloat(s.stddev[p], e.stddev, "stddev" + at);
    expectFloat(s.minimum[p], e.minimum, "minimum" + at);
    expectFloat(s.maximum[p], e.maximum, "maximum" + at);
    expectFloat(s.range[p], e.range, "range" + at);
    expectFloat(s.exceedance[p], e.exceedance, "exceedance" + at);
}

std::string errorMessage(const std::function<void()>& f) {
    try {
        f();
    } catch (const data::Error& error) {
        EXPECT_EQ(error.kind(), data::ErrorKind::InvalidArgument) << error.what();
        return error.what();
    }
    ADD_FAILURE() << "no data::Error thrown";
    return {};
}

}  // namespace

TEST(EnsembleStatistics, EveryStatisticByHandWithMissingValues) {
    const auto s = prep::computeEnsembleStatistics(threeMembers(), 2.0F);
    EXPECT_EQ(s.isovalue, 2.0F);
    EXPECT_EQ(s.members, (std::vector<std::size_t>{0, 1, 2}));
    ASSERT_EQ(s.count.size(), 8u);
    for (const auto* field :
         {&s.mean, &s.stddev, &s.minimum, &s.maximum, &s.range, &s.exceedance}) {
        ASSERT_EQ(field->size(), 8u);
    }
    // 0: {1, 2, 6}: mean 3; squares 4 + 1 + 9 = 14, / (3 - 1) = 7; one of three (6) > 2.
    expectPoint(s, 0, {3, 3, std::sqrt(7.0F), 1, 6, 5, 1.0F / 3.0F});
    // 1: {2, 4}: mean 3; squares 1 + 1 = 2, / 1; 2 is not > 2, 4 is: 1 of 2.
    expectPoint(s, 1, {2, 3, std::sqrt(2.0F), 2, 4, 2, 0.5F});
    // 2: {5} alone: n = 1 has no sample deviation.
    expectPoint(s, 2, {1, 5, kNaN, 5, 5, 0, 1});
    // 3: NaN, +inf, -inf are all missing: n = 0, everything else NaN.
    expectPoint(s, 3, {0, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN});
    // 4: {3, 3, 3}: no spread; all above.
    expectPoint(s, 4, {3, 3, 0, 3, 3, 0, 1});
    // 5: {0, 1, 2}: mean 1; squares 1 + 0 + 1 = 2, / 2 = 1; none > 2.
    expectPoint(s, 5, {3, 1, 1, 0, 2, 2, 0});
    // 6: {10, 20, 30}: mean 20; squares 100 + 0 + 100 = 200, / 2 = 100.
    expectPoint(s, 6, {3, 20, 10, 10, 30, 20, 1});
    // 7: {4, 2, 0}: mean 2; squares 4 + 0 + 4 = 8, / 2 = 4; only 4 > 2.
    expectPoint(s, 7, {3, 2, 2, 0, 4, 4, 1.0F / 3.0F});
    // The one cell has a missing corner in every member (point 2 in m0 and m1, point 3 in m2).
    ASSERT_EQ(s.levelCrossing.size(), 1u);
    EXPECT_TRUE(std::isnan(s.levelCrossing[0]));
}

TEST(EnsembleStatistics, SubsetOfMembers) {
    const auto e = threeMembers();
    const std::vector<std::size_t> members{2, 0};
    const auto s = prep::computeEnsembleStatistics(e, 2.0F, members);
    EXPECT_EQ(s.members, members);
    // 0: {6, 1}: mean 3.5; squares 6.25 + 6.25 = 12.5, / 1; 6 > 2.
    expectPoint(s, 0, {2, 3.5F, std::sqrt(12.5F), 1, 6, 5, 0.5F});
    // 1: {4, 2}: mean 3, squares 2.
    expectPoint(s, 1, {2, 3, std::sqrt(2.0F), 2, 4, 2, 0.5F});
    // 2: {5} (m0 misses it).
    expectPoint(s, 2, {1, 5, kNaN, 5, 5, 0, 1});
    // 3: -inf and NaN.
    expectPoint(s, 3, {0, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN});
    // 5: {2, 0}: mean 1; squares 1 + 1 = 2, / 1.
    expectPoint(s, 5, {2, 1, std::sqrt(2.0F), 0, 2, 2, 0});
    // 6: {30, 10}: mean 20; squares 200, / 1.
    expectPoint(s, 6, {2, 20, std::sqrt(200.0F), 10, 30, 20, 1});

    // One member: n < 2 at every point, so no standard deviation anywhere.
    const std::vector<std::size_t> one{1};
    const auto single = prep::computeEnsembleStatistics(e, 2.0F, one);
    expectPoint(single, 0, {1, 2, kNaN, 2, 2, 0, 0});
    expectPoint(single, 1, {0, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN});
    expectPoint(single, 6, {1, 20, kNaN, 20, 20, 0, 1});
}

TEST(EnsembleStatistics, BadSubsetsAreClearErrors) {
    const auto e = threeMembers();
    const std::vector<std::size_t> outOfRange{0, 3};
    EXPECT_NE(errorMessage([&] {
                  prep::computeEnsembleStatistics(e, 2.0F, outOfRange);
              }).find("member index 3 is out of range: the ensemble has 3 members (0 to 2)"),
              std::string::npos);
    const std::vector<std::size_t> twice{1, 2, 1};
    EXPECT_NE(errorMessage([&] {
                  prep::computeEnsembleStatistics(e, 2.0F, twice);
              }).find("member 1 ('') is listed twice"),
              std::string::npos);
    const std::vector<std::size_t> none;
    EXPECT_NE(
        errorMessage([&] { prep::computeEnsembleStatistics(e, 2.0F, none); }).find("no members"),
        std::string::npos);
    EXPECT_NE(errorMessage([&] { prep::computeEnsembleStatistics(e, kNaN); }).find("finite"),
              std::string::npos);
    data::Ensemble empty;
    EXPECT_NE(
        errorMessage([&] { prep::computeEnsembleStatistics(empty, 2.0F); }).find("no members"),
        std::string::npos);
    auto shortMember = e;
    shortMember.members[1].values.resize(7);
    EXPECT_NE(errorMessage([&] {
                  prep::computeEnsembleStatistics(shortMember, 2.0F);
              }).find("has 7 values but the grid has 8 points"),
              std::string::npos);
    prep::EnsembleStatisticsAccumulator accumulator(e.grid, 2.0F);
    const std::vector<float> seven(7, 1.0F);
    EXPECT_NE(errorMessage([&] { accumulator.add(seven); }).find("7 values"), std::string::npos);
}

TEST(EnsembleStatistics, LevelCrossingByHandWithAMissingCorner) {
    // 3 x 2 x 2 grid: two cells, cell 0 with corners i in {0, 1} and cell 1 with i in {1, 2}.
    // c = 2. Members (value 1 unless said):
    //   m0: all 1                               cell 0: no        cell 1: no
    //   m1: 3 at (0,0,0)                        cell 0: straddles cell 1: no
    //   m2: 3 at (1,0,0), a shared corner       cell 0: straddles cell 1: straddles
    //   m3: 3 at (0,0,0), NaN at (2,1,1)        cell 0: straddles cell 1: missing corner
    //   m4: all 2, 2.5 at (2,0,0)               cell 0: no (2 is not > 2)  cell 1: straddles
    //   m5: all 5                               cell 0: no        cell 1: no
    // cell 0: 3 of 6 members = 0.5; cell 1: 2 of the 5 with 8 finite corners = 0.4.
    auto e = test::analyticEnsemble(6, 3, 2, 2, [](auto m, auto, auto, auto) {
        return m == 4 ? 2.0F : (m == 5 ? 5.0F : 1.0F);
    });
    e.members[1].values[e.grid.index(0, 0, 0)] = 3;
    e.members[2].values[e.grid.index(1, 0, 0)] = 3;
    e.members[3].values[e.grid.index(0, 0, 0)] = 3;
    e.members[3].values[e.grid.index(2, 1, 1)] = kNaN;
    e.members[4].values[e.grid.index(2, 0, 0)] = 2.5F;
    const auto s = prep::computeEnsembleStatistics(e, 2.0F);
    ASSERT_EQ(prep::cellCount(e.grid), 2u);
    ASSERT_EQ(s.levelCrossing.size(), 2u);
    EXPECT_FLOAT_EQ(s.levelCrossing[prep::cellIndex(e.grid, 0, 0, 0)], 0.5F);
    EXPECT_FLOAT_EQ(s.levelCrossing[prep::cellIndex(e.grid, 1, 0, 0)], 0.4F);

    // Over m3 and m5 only: cell 0 straddles in m3 only (1 of 2); cell 1 has no member with
    // 8 finite corners but m5, which does not straddle (0 of 1).
    const std::vector<std::size_t> some{3, 5};
    const auto sub = prep::computeEnsembleStatistics(e, 2.0F, some);
    EXPECT_FLOAT_EQ(sub.levelCrossing[0], 0.5F);
    EXPECT_FLOAT_EQ(sub.levelCrossing[1], 0.0F);
    // Over m3 alone, cell 1 has no member with all corners: NaN.
    const std::vector<std::size_t> m3{3};
    EXPECT_TRUE(std::isnan(prep::computeEnsembleStatistics(e, 2.0F, m3).levelCrossing[1]));
}

TEST(EnsembleStatistics, MatchesTheDefinitionOnEveryPointAndCellInAnyMemberOrder) {
    // 7 random members on 5 x 4 x 3 points with 10 % missing, against the definitions computed
    // directly (two passes, cells from their 8 corners): checks every index of points and
    // cells, in x, y and z.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> value(0.0F, 10.0F);
    std::uniform_real_distribution<float> unit(0.0F, 1.0F);
    const std::size_t nx = 5, ny = 4, nz = 3, members = 7;
    auto e = test::analyticEnsemble(members, nx, ny, nz, [&](auto, auto, auto, auto) {
        return unit(rng) < 0.1F ? kNaN : value(rng);
    });
    const float c = 5.0F;
    const auto s = prep::computeEnsembleStatistics(e, c);
    for (std::size_t p = 0; p < e.grid.pointCount(); ++p) {
        std::vector<double> f;
        for (const auto& m : e.members) {
            if (!std::isnan(m.values[p])) f.push_back(m.values[p]);
        }
        const double n = static_cast<double>(f.size());
        double sum = 0.0, squares = 0.0, above = 0.0;
        for (const double v : f) sum += v;
        const double mean = sum / n;
        for (const double v : f) {
            squares += (v - mean) * (v - mean);
            above += v > c ? 1.0 : 0.0;
        }
        const auto [lo, hi] = std::minmax_element(f.begin(), f.end());
        const float none = kNaN;
        expectPoint(
            s, p,
            {static_cast<float>(n), f.empty() ? none : static_cast<float>(mean),
             f.size() < 2 ? none : static_cast<float>(std::sqrt(squares / (n - 1))),
             f.empty() ? none : static_cast<float>(*lo), f.empty() ? none : static_cast<float>(*hi),
             f.empty() ? none : static_cast<float>(*hi - *lo),
             f.empty() ? none : static_cast<float>(above / n)});
    }
    ASSERT_EQ(s.levelCrossing.size(), (nx - 1) * (ny - 1) * (nz - 1));
    for (std::size_t k = 0; k + 1 < nz; ++k)
        for (std::size_t j = 0; j + 1 < ny; ++j)
            for (std::size_t i = 0; i + 1 < nx; ++i) {
                int valid = 0, crossing = 0;
                for (const auto& m : e.members) {
                    bool finite = true, over = false, under = false;
                    for (int corner = 0; corner < 8; ++corner) {
                        const float v = m.values[e.grid.index(
                            i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1))];
                        finite = finite && !std::isnan(v);
                        over = over || v > c;
                        under = under || v <= c;
                    }
                    valid += finite ? 1 : 0;
                    crossing += finite && over && under ? 1 : 0;
                }
                const float expected =
                    valid == 0 ? kNaN : static_cast<float>(crossing) / static_cast<float>(valid);
                expectFloat(s.levelCrossing[prep::cellIndex(e.grid, i, j, k)], expected,
                            "cell " + std::to_string(i) + "," + std::to_string(j) + "," +
                                std::to_string(k));
            }

    // A member at a time, as a reader would add them, in reverse order: the same statistics.
    prep::EnsembleStatisticsAccumulator accumulator(e.grid, c);
    for (std::size_t m = members; m-- > 0;) accumulator.add(e.members[m].values);
    const auto streamed = accumulator.result();
    for (std::size_t p = 0; p < e.grid.pointCount(); ++p) {
        expectPoint(streamed, p,
                    {s.count[p], s.mean[p], s.stddev[p], s.minimum[p], s.maximum[p], s.range[p],
                     s.exceedance[p]});
    }
    for (std::size_t cell = 0; cell < s.levelCrossing.size(); ++cell) {
        expectFloat(streamed.levelCrossing[cell], s.levelCrossing[cell], "streamed cell");
    }
}

TEST(EnsembleStatistics, KeepsPrecisionForLargeValues) {
    // 1e6 + {0, 0.25, 0.5, 0.75} (exact floats): mean 1e6 + 0.375; squares
    // 0.25^2 (2.25 + 0.25 + 0.25 + 2.25) = 0.3125, / 3: stddev = sqrt(0.3125 / 3) = 0.3227486.
    // A float sum of squares around 0 would lose all of it.
    const auto e = test::analyticEnsemble(4, 2, 2, 2, [](auto m, auto, auto, auto) {
        return 1.0e6F + 0.25F * static_cast<float>(m);
    });
    const auto s = prep::computeEnsembleStatistics(e, 1.0e6F);
    for (std::size_t p = 0; p < 8; ++p) {
        EXPECT_EQ(s.mean[p], 1000000.375F);
        EXPECT_NEAR(s.stddev[p], 0.3227486F, 1e-6F);
        EXPECT_FLOAT_EQ(s.exceedance[p], 0.75F);
    }
}

TEST(EnsembleStatistics, CancelThrowsAndProgressIsMonotonic) {
    // 64 levels, summed on several threads.
    const std::size_t levels = 64;
    const auto e = test::analyticEnsemble(
        6, 8, 8, levels, [](auto m, auto, auto, auto) { return static_cast<float>(m); });
    std::vector<double> fractions;
    prep::computeEnsembleStatistics(e, 2.5F, {}, [&](double f) { fractions.push_back(f); });
    ASSERT_GE(fractions.size(), levels);  // at least once per level
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);

    std::stop_source stop;
    std::atomic<int> calls = 0;
    EXPECT_THROW(prep::computeEnsembleStatistics(e, 2.5F, stop.get_token(),
                                                 [&](double) {
                                                     if (++calls == 2) stop.request_stop();
                                                 }),
                 data::Cancelled);
    // Levels already begun on other threads finish; no member is added after the request.
    EXPECT_LT(calls, static_cast<int>(levels) / 2) << "the step must stop soon after the request";
}

#include "preprocessing/inclusion_depth.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "data/error.h"
#include "fixtures.h"
#include "preprocessing/band_envelope.h"
#include "tests/support/special_values.h"

using namespace ensil;

namespace {

using test::kInf;
using test::kNaN;

// Members on a 2 x 2 x 2 grid (points 0..7) whose inside sets at c = 0.5 are the given points:
// 1 there, 0 elsewhere.
data::Ensemble setsEnsemble(const std::vector<std::set<std::size_t>>& sets) {
    return test::analyticEnsemble(sets.size(), 2, 2, 2, [&](auto m, auto i, auto j, auto k) {
        return sets[m].contains(i + 2 * j + 4 * k) ? 1.0F : 0.0F;
    });
}

std::vector<float> indicator(const std::set<std::size_t>& points) {
    std::vector<float> values(8, 0.0F);
    for (const std::size_t p : points) values[p] = 1.0F;
    return values;
}

// The band's intersection and union as 0/1 on the points: where its members' lowest value
// (inside every one) or highest value (inside any) is above c (band_envelope.h).
std::vector<float> insideEvery(const data::Ensemble& e, const prep::ContourBoxplot& box) {
    const auto lowest = prep::computeBandEnvelope(e, box.bandMembers).lowest;
    std::vector<float> out;
    for (const float v : lowest) out.push_back(v > box.isovalue ? 1.0F : 0.0F);
    return out;
}
std::vector<float> insideAny(const data::Ensemble& e, const prep::ContourBoxplot& box) {
    const auto highest = prep::computeBandEnvelope(e, box.bandMembers).highest;
    std::vector<float> out;
    for (const float v : highest) out.push_back(v > box.isovalue ? 1.0F : 0.0F);
    return out;
}
}  // namespace

TEST(InclusionDepth, FourMembersByHandWithMissingValuesAndAnEmptyInsideSet) {
    // Inside sets: A = {0,1,2,3}, B = {0,1,2}, C = {0,...,5}, D = {}. B is NaN at point 3 and
    // D has NaN, +inf and -inf at points 0, 1, 2: missing values are never inside (were they,
    // B would be {0,1,2,3} and D {1}).
    auto e = setsEnsemble({{0, 1, 2, 3}, {0, 1, 2}, {0, 1, 2, 3, 4, 5}, {}});
    e.members[1].values[3] = kNaN;
    e.members[3].values[0] = kNaN;
    e.members[3].values[1] = kInf;
    e.members[3].values[2] = -kInf;
    const auto box = prep::computeContourBoxplot(e, 0.5F);
    EXPECT_EQ(box.isovalue, 0.5F);
    EXPECT_EQ(box.insidePoints, (std::vector<std::size_t>{4, 3, 6, 0}));
    // e(i in j) = 1 - |B_i \ B_j| / |B_i|:
    //   A in B = 1 - 1/4 = 3/4, A in C = 1, A in D = 0;   B in A = B in C = 1, B in D = 0;
    //   C in A = 1 - 2/6 = 2/3, C in B = 1 - 3/6 = 1/2, C in D = 0;   D in anything = 1.
    // A: min((3/4 + 1 + 0) / 3, (1 + 2/3 + 1) / 3) = min(7/12, 8/9) = 7/12
    // B: min((1 + 1 + 0) / 3, (3/4 + 1/2 + 1) / 3) = min(2/3, 3/4) = 2/3
    // C: min((2/3 + 1/2 + 0) / 3, (1 + 1 + 1) / 3) = min(7/18, 1) = 7/18
    // D: empty inside set, depth 0.
    ASSERT_EQ(box.depth.size(), 4u);
    EXPECT_NEAR(box.depth[0], 7.0 / 12.0, 1e-12);
    EXPECT_NEAR(box.depth[1], 2.0 / 3.0, 1e-12);
    EXPECT_NEAR(box.depth[2], 7.0 / 18.0, 1e-12);
    EXPECT_EQ(box.depth[3], 0.0);
    // The median is B; the band the ceil(4 / 2) = 2 deepest, B and A: between A & B = {0,1,2}
    // and A | B = {0,1,2,3}.
    EXPECT_EQ(box.median, 1u);
    EXPECT_EQ(box.bandMembers, (std::vector<std::size_t>{1, 0}));
    EXPECT_EQ(insideEvery(e, box), indicator({0, 1, 2}));
    EXPECT_EQ(insideAny(e, box), indicator({0, 1, 2, 3}));
    // Sorted depths 0, 7/18, 7/12, 2/3. Q1 at position 3 * 0.25 = 0.75: 0.75 * 7/18 = 7/24;
    // Q3 at 2.25: 7/12 + 0.25 (2/3 - 7/12) = 29/48. IQR = 29/48 - 14/48 = 15/48, fence
    // 14/48 - 1.5 * 15/48 = -8.5/48: even D's depth 0 is no outlier.
    EXPECT_NEAR(box.lowerFence, -8.5 / 48.0, 1e-12);
    EXPECT_TRUE(box.outliers.empty());
}

TEST(ContourBoxplot, OutlierFenceMedianTiesAndBandByHand) {
    // m0 = {0,...,5}, m1 = {0,1,2,3,4,6} (as large as m0, different), m2 = {0,...,4},
    // m3 = {0,1,2,3}, m4 = {0}; |m0 & m1| = 5, the others nested in both.
    const auto e =
        setsEnsemble({{0, 1, 2, 3, 4, 5}, {0, 1, 2, 3, 4, 6}, {0, 1, 2, 3, 4}, {0, 1, 2, 3}, {0}});
    const auto box = prep::computeContourBoxplot(e, 0.5F);
    // m0: in others (5/6 + 5/6 + 4/6 + 1/6) / 4 = 0.625; others in it (5/6 + 1 + 1 + 1) / 4.
    // m1: the same by symmetry, 0.625.
    // m2: in others (1 + 1 + 4/5 + 1/5) / 4 = 0.75; others in it (5/6 + 5/6 + 1 + 1) / 4.
    // m3: in others (1 + 1 + 1 + 1/4) / 4 = 13/16; others in it (4/6 + 4/6 + 4/5 + 1) / 4 = 47/60.
    // m4: in others 1; others in it (1/6 + 1/6 + 1/5 + 1/4) / 4 = 47/240.
    ASSERT_EQ(box.depth.size(), 5u);
    EXPECT_NEAR(box.depth[0], 0.625, 1e-12);
    EXPECT_NEAR(box.depth[1], 0.625, 1e-12);
    EXPECT_NEAR(box.depth[2], 0.75, 1e-12);
    EXPECT_NEAR(box.depth[3], 47.0 / 60.0, 1e-12);
    EXPECT_NEAR(box.depth[4], 47.0 / 240.0, 1e-12);
    // The median is m3, not the largest set.
    EXPECT_EQ(box.median, 3u);
    // ceil(5 / 2) = 3 deepest: m3, m2, then m0 of the equally deep m0 and m1 (lower index), so
    // the outer surface holds point 5 (m0's) and not point 6 (m1's).
    EXPECT_EQ(box.bandMembers, (std::vector<std::size_t>{3, 2, 0}));
    EXPECT_EQ(insideEvery(e, box), indicator({0, 1, 2, 3}));
    EXPECT_EQ(insideAny(e, box), indicator({0, 1, 2, 3, 4, 5}));
    // Sorted 47/240, 0.625, 0.625, 0.75, 47/60: Q1 = 0.625 (position 1), Q3 = 0.75 (position 3),
    // fence 0.625 - 1.5 * 0.125 = 0.4375: m4 alone is below it.
    EXPECT_NEAR(box.lowerFence, 0.4375, 1e-12);
    EXPECT_EQ(box.outliers, (std::vector<std::size_t>{4}));
}

TEST(ContourBoxplot, OneMember) {
    // One member with a surface: depth 1 (nothing to compare it with), its own median and band.
    const auto one = setsEnsemble({{2, 3}});
    const auto box = prep::computeContourBoxplot(one, 0.5F);
    EXPECT_EQ(box.depth, (std::vector<double>{1.0}));
    EXPECT_EQ(box.median, 0u);
    EXPECT_EQ(box.bandMembers, (std::vector<std::size_t>{0}));
    EXPECT_EQ(insideEvery(one, box), indicator({2, 3}));
    EXPECT_EQ(insideAny(one, box), indicator({2, 3}));
    EXPECT_TRUE(box.outliers.empty());
    // Without a surface: depth 0.
    EXPECT_EQ(prep::computeContourBoxplot(setsEnsemble({{}}), 0.5F).depth,
              (std::vector<double>{0.0}));
}

TEST(InclusionDepth, MatchesTheDefinitionPointByPoint) {
    // 9 random members on 9 x 5 x 3 = 135 points (three 64-bit words, the last one partial),
    // 10 % missing, one member entirely below c: against the definition counted point by point.
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0F, 1.0F);
    auto e = test::analyticEnsemble(9, 9, 5, 3, [&](auto m, auto i, auto, auto) {
        if (unit(rng) < 0.1F) return kNaN;
        return m == 8 ? -1.0F : unit(rng) + 0.05F * static_cast<float>(i);
    });
    const float c = 0.6F;
    const std::size_t n = e.memberCount(), points = e.grid.pointCount();
    const auto isInside = [&](std::size_t m, std::size_t p) { return e.members[m].values[p] > c; };
    const auto containment = [&](std::size_t i, std::size_t j) {
        double size = 0.0, outside = 0.0;
        for (std::size_t p = 0; p < points; ++p) {
            if (!isInside(i, p)) continue;
            size += 1.0;
            if (!isInside(j, p)) outside += 1.0;
        }
        return size == 0.0 ? 1.0 : 1.0 - outside / size;
    };
    const auto box = prep::computeContourBoxplot(e, c);
    for (std::size_t i = 0; i < n; ++i) {
        double in = 0.0, out = 0.0, size = 0.0;
        for (std::size_t p = 0; p < points; ++p) size += isInside(i, p) ? 1.0 : 0.0;
        for (std::size_t j = 0; j < n; ++j) {
            if (j == i) continue;
            in += containment(i, j);
            out += containment(j, i);
        }
        const double expected = size == 0.0 ? 0.0 : std::min(in, out) / static_cast<double>(n - 1);
        EXPECT_NEAR(box.depth[i], expected, 1e-12) << "member " << i;
        EXPECT_EQ(box.insidePoints[i], static_cast<std::size_t>(size)) << "member " << i;
    }
    EXPECT_EQ(box.depth[8], 0.0);
    ASSERT_EQ(box.bandMembers.size(), 5u);
    const std::vector<float> every = insideEvery(e, box), any = insideAny(e, box);
    for (std::size_t p = 0; p < points; ++p) {
        std::size_t count = 0;
        for (const std::size_t m : box.bandMembers) count += isInside(m, p) ? 1 : 0;
        EXPECT_EQ(every[p], count == 5 ? 1.0F : 0.0F) << "point " << p;
        EXPECT_EQ(any[p], count > 0 ? 1.0F : 0.0F) << "point " << p;
    }
}

TEST(InclusionDepth, LinearQuantileIsNumpysDefault) {
    // numpy.percentile([1, 2, 3, 4], [0, 25, 50, 75, 100]) = [1, 1.75, 2.5, 3.25, 4].
    const std::vector<double> v{1, 2, 3, 4};
    EXPECT_DOUBLE_EQ(prep::linearQuantile(v, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(prep::linearQuantile(v, 0.25), 1.75);
    EXPECT_DOUBLE_EQ(prep::linearQuantile(v, 0.5), 2.5);
    EXPECT_DOUBLE_EQ(prep::linearQuantile(v, 0.75), 3.25);
    EXPECT_DOUBLE_EQ(prep::linearQuantile(v, 1.0), 4.0);
    // numpy.percentile([0, 10, 30], 25) = 5 (position 0.5).
    EXPECT_DOUBLE_EQ(prep::linearQuantile(std::vector<double>{0, 10, 30}, 0.25), 5.0);
    EXPECT_DOUBLE_EQ(prep::linearQuantile(std::vector<double>{7}, 0.75), 7.0);
    EXPECT_THROW(prep::linearQuantile(std::vector<double>{}, 0.5), data::Error);
    EXPECT_THROW(prep::linearQuantile(v, 1.5), data::Error);
}

TEST(ContourBoxplot, ErrorsCancelAndProgress) {
    data::Ensemble empty;
    EXPECT_THROW(prep::computeContourBoxplot(empty, 0.5F), data::Error);
    const auto e = test::analyticEnsemble(
        6, 8, 8, 8, [](auto m, auto i, auto, auto) { return static_cast<float>(m + i); });
    try {
        prep::computeContourBoxplot(e, kNaN);
        ADD_FAILURE() << "a NaN isovalue must be refused";
    } catch (const data::Error& error) {
        EXPECT_EQ(error.kind(), data::ErrorKind::InvalidArgument);
        EXPECT_NE(std::string(error.what()).find("finite"), std::string::npos) << error.what();
    }

    std::vector<double> fractions;
    prep::computeContourBoxplot(e, 5.0F, {}, [&](double f) { fractions.push_back(f); });
    ASSERT_FALSE(fractions.empty());
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);

    std::stop_source stop;
    int calls = 0;
    EXPECT_THROW(prep::computeContourBoxplot(e, 5.0F, stop.get_token(),
                                             [&](double) {
                                                 if (++calls == 2) stop.request_stop();
                                             }),
                 data::Cancelled);
    // Members run on every core: those already begun when the stop came (one a thread besides
    // the one that asked) still finish and report; no other starts.
    const int threads = tbb::this_task_arena::max_concurrency();
    EXPECT_GE(calls, 2);
    EXPECT_LE(calls, 1 + threads) << "the step must stop at the members begun before the request";
    EXPECT_LT(static_cast<std::size_t>(calls), fractions.size());
}

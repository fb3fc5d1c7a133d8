// The distance matrix as partial sums over blocks of grid points (METHODS.md section 7): any
// partition of the points, merged in any order or summed as raw arrays (as an MPI reduction
// does), gives the matrix of the whole grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "data/error.h"
#include "preprocessing/similarity.h"
#include "tests/preprocessing/fixtures.h"
#include "tests/support/special_values.h"

using namespace ensil;

namespace {

using test::kNaN;

// The points [first, last) of every member, as DistanceSums::add takes them.
std::vector<std::span<const float>> pointsOf(const data::Ensemble& e, std::size_t first,
                                             std::size_t last) {
    std::vector<std::span<const float>> part;
    for (const data::Member& m : e.members)
        part.emplace_back(m.values.data() + first, last - first);
    return part;
}

// The definition, point by point in double.
double directDistance(const data::Ensemble& e, float isovalue, std::size_t i, std::size_t j) {
    double sum = 0.0;
    std::size_t common = 0;
    for (std::size_t p = 0; p < e.grid.pointCount(); ++p) {
        const double a = e.members[i].values[p], b = e.members[j].values[p];
        if (!std::isfinite(a) || !std::isfinite(b)) continue;
        const double diff = std::sqrt(std::abs(a - isovalue)) - std::sqrt(std::abs(b - isovalue));
        sum += diff * diff;
        ++common;
    }
    return sum / static_cast<double>(common);
}

// 6 members on 40 x 30 x 20 points with some missing values in the first third.
data::Ensemble randomEnsemble() {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<float> value(0.0F, 50.0F);
    std::uniform_int_distribution<int> missing(0, 6);
    return test::analyticEnsemble(6, 40, 30, 20, [&](auto, auto, auto, auto k) {
        return k < 7 && missing(rng) == 0 ? kNaN : value(rng);
    });
}

void expectSameMatrix(const prep::DistanceMatrix& a, const prep::DistanceMatrix& b,
                      double relative) {
    ASSERT_EQ(a.size, b.size);
    for (std::size_t i = 0; i < a.size; ++i) {
        for (std::size_t j = 0; j < a.size; ++j) {
            EXPECT_NEAR(a.at(i, j), b.at(i, j), relative * std::abs(b.at(i, j)))
                << "i=" << i << " j=" << j;
        }
    }
    EXPECT_EQ(a.pairsWithoutOverlap, b.pairsWithoutOverlap);
}

}  // namespace

TEST(DistanceSums, AnyPartitionOfThePointsMergedInAnyOrderGivesTheWholeMatrix) {
    const data::Ensemble e = randomEnsemble();
    const float isovalue = 25.0F;
    const std::size_t points = e.grid.pointCount();
    const prep::DistanceMatrix whole = prep::computeDistanceMatrix(e, isovalue);
    std::mt19937_64 rng(5);
    for (int trial = 0; trial < 5; ++trial) {
        // Random cut points, one part of a single point among them.
        std::vector<std::size_t> cuts{0, 1, points};
        std::uniform_int_distribution<std::size_t> cut(1, points - 1);
        for (int c = 0; c < 2 + 3 * trial; ++c) cuts.push_back(cut(rng));
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        std::vector<prep::DistanceSums> parts;
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
            parts.emplace_back(e.memberCount(), isovalue);
            parts.back().add(pointsOf(e, cuts[c], cuts[c + 1]));
        }
        std::shuffle(parts.begin(), parts.end(), rng);
        prep::DistanceSums merged(e.memberCount(), isovalue);
        for (const auto& part : parts) merged.merge(part);
        EXPECT_EQ(merged.points(), static_cast<double>(points));
        expectSameMatrix(merged.finish(), whole, 1e-12);
    }
}

TEST(DistanceSums, RawArraysSummedElementByElementAreAMerge) {
    // What an MPI_SUM reduction of raw() does between ranks.
    const data::Ensemble e = randomEnsemble();
    const std::size_t points = e.grid.pointCount();
    prep::DistanceSums a(e.memberCount(), 25.0F), b(e.memberCount(), 25.0F);
    a.add(pointsOf(e, 0, points / 3));
    b.add(pointsOf(e, points / 3, points));
    std::vector<double> reduced(a.raw().begin(), a.raw().end());
    ASSERT_EQ(reduced.size(), b.raw().size());
    for (std::size_t k = 0; k < reduced.size(); ++k) reduced[k] += b.raw()[k];
    std::copy(reduced.begin(), reduced.end(), a.raw().begin());
    expectSameMatrix(a.finish(), prep::computeDistanceMatrix(e, 25.0F), 1e-12);
}

TEST(DistanceSums, MatchesTheDirectFormulaWithMissingValues) {
    const data::Ensemble e = randomEnsemble();
    const std::size_t points = e.grid.pointCount();
    prep::DistanceSums sums(e.memberCount(), 25.0F);
    for (std::size_t first = 0; first < points; first += 1000) {
        sums.add(pointsOf(e, first, std::min(points, first + 1000)));
    }
    const prep::DistanceMatrix d = sums.finish();
    for (std::size_t i = 0; i < e.memberCount(); ++i) {
        EXPECT_EQ(d.at(i, i), 0.0);
        for (std::size_t j = 0; j < i; ++j) {
            const double expected = directDistance(e, 25.0F, i, j);
            EXPECT_NEAR(d.at(i, j), expected, 1e-9 * expected) << "i=" << i << " j=" << j;
        }
    }
}

TEST(DistanceSums, APairCountsOnlyPointsValidInBothEvenAcrossParts) {
    // Over 8 points (mu = 0): A is 4 (s = 2) on the first half and missing on the second, B the
    // reverse (s = 1), C is 1 everywhere (s = 1). Each part has valid points for every member,
    // but A and B never share one: (A, B) has no overlap; d(A, C) = (2 - 1)^2 over 4 points = 1;
    // d(B, C) = 0. With the parts split as the halves, the per-pair counts must not mix.
    // 2 x 2 x 2 points; the first half is the layer k = 0.
    const auto e = test::analyticEnsemble(3, 2, 2, 2, [](auto m, auto, auto, auto k) {
        if (m == 0) return k == 0 ? 4.0F : kNaN;
        if (m == 1) return k == 0 ? kNaN : -1.0F;
        return 1.0F;
    });
    prep::DistanceSums first(3, 0.0F), second(3, 0.0F);
    first.add(pointsOf(e, 0, 4));
    second.add(pointsOf(e, 4, 8));
    first.merge(second);
    const prep::DistanceMatrix d = first.finish();
    EXPECT_DOUBLE_EQ(d.at(0, 2), 1.0);
    EXPECT_DOUBLE_EQ(d.at(1, 2), 0.0);
    using Pair = std::pair<std::size_t, std::size_t>;
    EXPECT_EQ(d.pairsWithoutOverlap, (std::vector<Pair>{{0, 1}}));
    EXPECT_DOUBLE_EQ(d.at(0, 1), 1.0);  // placed at the farthest measured distance
}

TEST(DistanceSums, RefusesPartsOfOtherMembersOrIsovalues) {
    prep::DistanceSums sums(3, 1.0F);
    EXPECT_THROW(sums.merge(prep::DistanceSums(4, 1.0F)), data::Error);
    EXPECT_THROW(sums.merge(prep::DistanceSums(3, 2.0F)), data::Error);
    const std::vector<float> a(5, 1.0F), b(4, 1.0F);
    const std::vector<std::span<const float>> two{a, a};
    EXPECT_THROW(sums.add(two), data::Error);
    const std::vector<std::span<const float>> uneven{a, a, b};
    EXPECT_THROW(sums.add(uneven), data::Error);
}

TEST(DistanceSums, NoPointsAddedCannotBeMeasured) {
    const prep::DistanceSums sums(2, 1.0F);
    EXPECT_THROW((void)sums.finish(), data::Error);
}

TEST(DistanceSums, ASubsetOfTheMembersIsTheirOwnSums) {
    // Members 1 and 3 left out after their points were added: the rest's matrix equals the one
    // computed without them.
    const data::Ensemble e = randomEnsemble();
    prep::DistanceSums all(e.memberCount(), 25.0F);
    all.add(pointsOf(e, 0, e.grid.pointCount()));
    const std::vector<std::size_t> keep{0, 2, 4, 5};
    data::Ensemble fewer = e;
    fewer.members = {e.members[0], e.members[2], e.members[4], e.members[5]};
    expectSameMatrix(all.subset(keep).finish(), prep::computeDistanceMatrix(fewer, 25.0F), 1e-12);
    const std::vector<std::size_t> beyond{0, 6};
    EXPECT_THROW((void)all.subset(beyond), data::Error);
}

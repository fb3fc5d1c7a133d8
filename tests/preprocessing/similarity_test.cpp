#include "preprocessing/similarity.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "data/error.h"
#include "fixtures.h"
#include "tests/support/special_values.h"

using namespace ensil;

namespace {

using test::kNaN;

// The definition, summed point by point in double: the reference the matrix products must meet.
double referenceDistance(const data::Ensemble& e, float isovalue, std::size_t i, std::size_t j) {
    const double mu = isovalue;
    double sum = 0.0;
    std::size_t common = 0;
    for (std::size_t p = 0; p < e.grid.pointCount(); ++p) {
        const float a = e.members[i].values[p], b = e.members[j].values[p];
        if (std::isnan(a) || std::isnan(b)) continue;
        const double diff = std::sqrt(std::abs(a - mu)) - std::sqrt(std::abs(b - mu));
        sum += diff * diff;
        ++common;
    }
    return common > 0 ? sum / static_cast<double>(common) : std::numeric_limits<double>::infinity();
}

}  // namespace

TEST(Similarity, ConstantMembersGiveSquaredDifferencesOfRootDistances) {
    // mu = 10; c = 10, 14, 1, 35, 19 -> |c - mu| = 0, 4, 9, 25, 9 -> roots 0, 2, 3, 5, 3, so
    // d(i, j) = (r_i - r_j)^2 exactly at every point, and so is its mean over the grid.
    const std::vector<float> c{10.0F, 14.0F, 1.0F, 35.0F, 19.0F};
    const std::vector<double> root{0.0, 2.0, 3.0, 5.0, 3.0};
    const auto e =
        test::analyticEnsemble(5, 8, 4, 2, [&](auto m, auto, auto, auto) { return c[m]; });
    const prep::DistanceMatrix d = prep::computeDistanceMatrix(e, 10.0F);
    ASSERT_EQ(d.size, 5u);
    ASSERT_EQ(d.values.size(), 25u);
    for (std::size_t i = 0; i < 5; ++i) {
        for (std::size_t j = 0; j < 5; ++j) {
            const double expected = (root[i] - root[j]) * (root[i] - root[j]);
            EXPECT_DOUBLE_EQ(d.at(i, j), expected) << "i=" << i << " j=" << j;
        }
    }
    // Members 2 and 4 lie on opposite sides of the isovalue at the same distance: identical.
    EXPECT_EQ(d.at(2, 4), 0.0);
}

TEST(Similarity, CountsOnlyPointsValidInBothMembers) {
    // 2 x 2 x 2 grid, point p = i + 2 j + 4 k, mu = 0:
    //   A: f = p^2            -> s = p            (all 8 points valid)
    //   B: f = 1 or -1        -> s = 1            (missing at p = 1, 4)
    //   C: f = 4 at p = 1     -> s = 2            (missing everywhere else)
    //   D: f = 0 at p = 1, 4  -> s = 0            (valid exactly where B is missing)
    // d(A,B): common p = 0,2,3,5,6,7: (0-1)^2+(2-1)^2+(3-1)^2+(5-1)^2+(6-1)^2+(7-1)^2
    //         = 1+1+4+16+25+36 = 83 over m = 6.
    // d(A,C): common p = 1: (1-2)^2 = 1 over m = 1.         d(B,C): no common point.
    // d(A,D): common p = 1, 4: (1-0)^2 + (4-0)^2 = 17 over m = 2.
    // d(C,D): common p = 1: (2-0)^2 = 4 over m = 1.         d(B,D): no common point.
    // The pairs without a common point are placed at the largest measured distance, 83 / 6.
    const auto e = test::analyticEnsemble(4, 2, 2, 2, [](auto m, auto i, auto j, auto k) {
        const auto p = static_cast<float>(i + 2 * j + 4 * k);
        const bool bMissing = p == 1.0F || p == 4.0F;
        switch (m) {
            case 0:
                return p * p;
            case 1:
                return bMissing ? kNaN : (p == 7.0F ? -1.0F : 1.0F);
            case 2:
                return p == 1.0F ? 4.0F : kNaN;
            default:
                return bMissing ? 0.0F : kNaN;
        }
    });
    const auto d = prep::computeDistanceMatrix(e, 0.0F);
    EXPECT_DOUBLE_EQ(d.at(0, 1), 83.0 / 6.0);
    EXPECT_DOUBLE_EQ(d.at(0, 2), 1.0);
    EXPECT_DOUBLE_EQ(d.at(1, 2), 83.0 / 6.0);
    EXPECT_DOUBLE_EQ(d.at(2, 1), 83.0 / 6.0);
    EXPECT_DOUBLE_EQ(d.at(0, 3), 17.0 / 2.0);
    EXPECT_DOUBLE_EQ(d.at(2, 3), 4.0);
    EXPECT_DOUBLE_EQ(d.at(1, 3), 83.0 / 6.0);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(d.at(i, i), 0.0);
    using Pair = std::pair<std::size_t, std::size_t>;
    EXPECT_EQ(d.pairsWithoutOverlap, (std::vector<Pair>{{1, 2}, {1, 3}}));
}

TEST(Similarity, EveryDistanceIsMeasuredWhenEveryPairOverlaps) {
    const auto e = test::analyticEnsemble(
        3, 4, 4, 2, [](auto m, auto i, auto, auto) { return static_cast<float>(m + i); });
    EXPECT_TRUE(prep::computeDistanceMatrix(e, 1.0F).pairsWithoutOverlap.empty());
}

TEST(Similarity, MembersOfWhichNoTwoOverlapCannotBeComparedAndSaySo) {
    // Each member is valid only in its own column i == m: no pair has a common point.
    const auto e = test::analyticEnsemble(
        3, 3, 2, 2, [](auto m, auto i, auto, auto) { return i == m ? 1.0F : kNaN; });
    try {
        (void)prep::computeDistanceMatrix(e, 0.0F);
        FAIL() << "members with no common point were compared";
    } catch (const data::Error& error) {
        EXPECT_EQ(error.kind(), data::ErrorKind::AllValuesMissing);
        EXPECT_NE(std::string(error.what()).find("no two can be compared"), std::string::npos)
            << error.what();
    }
}

TEST(Similarity, MatrixProductsMatchAPlainLoopOverRandomFields) {
    // 64 x 64 x 40 = 163840 points: several blocks, the last one short. NaNs only in the
    // first 60000 points, so both the masked and the mask-free path of a block are used.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<float> value(0.0F, 60.0F);
    std::uniform_int_distribution<int> missing(0, 9);
    std::size_t point = 0;
    const std::size_t members = 7;
    auto e = test::analyticEnsemble(members, 64, 64, 40, [&](auto, auto, auto, auto) {
        const bool early = (point++ % 163840) < 60000;
        return early && missing(rng) == 0 ? kNaN : value(rng);
    });
    const float isovalue = 30.0F;
    const auto d = prep::computeDistanceMatrix(e, isovalue);
    for (std::size_t i = 0; i < members; ++i) {
        EXPECT_EQ(d.at(i, i), 0.0);
        for (std::size_t j = 0; j < i; ++j) {
            EXPECT_EQ(d.at(i, j), d.at(j, i)) << "not symmetric at " << i << ", " << j;
            const double expected = referenceDistance(e, isovalue, i, j);
            EXPECT_NEAR(d.at(i, j), expected, 1e-9 * expected) << "i=" << i << " j=" << j;
        }
    }
}

TEST(Similarity, TheMatrixIsTheSameToTheLastBitOnOneThreadOrMany) {
    // 40 members of 64 x 64 x 40 points: several parts of blocks, summed on as many threads as
    // run, must give exactly the matrix one thread gives, so a result never depends on the
    // machine it was computed on.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<float> value(0.0F, 60.0F);
    const auto e =
        test::analyticEnsemble(40, 64, 64, 40, [&](auto, auto, auto, auto) { return value(rng); });
    auto computeOn = [&](int threads) {
        prep::DistanceMatrix d;
        tbb::task_arena(threads).execute([&] { d = prep::computeDistanceMatrix(e, 30.0F); });
        return d;
    };
    const prep::DistanceMatrix one = computeOn(1), many = computeOn(4);
    ASSERT_EQ(one.values.size(), many.values.size());
    for (std::size_t k = 0; k < one.values.size(); ++k) {
        ASSERT_EQ(one.values[k], many.values[k]) << "entry " << k;
    }
}

TEST(Similarity, IdenticalMembersAreAtDistanceZeroUpToRounding) {
    // The expanded form sum s_i^2 + sum s_j^2 - 2 sum s_i s_j cancels for identical members;
    // what is left must be rounding noise, far below the smallest real distance of the data.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<float> value(0.0F, 60.0F);
    std::vector<float> field(32 * 32 * 16);
    for (float& v : field) v = value(rng);
    const auto e = test::analyticEnsemble(3, 32, 32, 16, [&](auto m, auto i, auto j, auto k) {
        const float v = field[i + 32 * (j + 32 * k)];
        return m == 2 ? v + 0.01F : v;
    });
    const auto d = prep::computeDistanceMatrix(e, 30.0F);
    EXPECT_GE(d.at(0, 1), 0.0);
    EXPECT_LT(d.at(0, 1), 1e-12);  // mean s^2 is about 15 here
    EXPECT_NEAR(d.at(0, 2), referenceDistance(e, 30.0F, 0, 2), 1e-12);
    EXPECT_GT(d.at(0, 2), 1e-6);
}

TEST(Similarity, InfinitiesCountAsMissing) {
    // Member 1 is +inf on half the points: only the other half counts, d = (3 - 1)^2 = 4.
    const auto e = test::analyticEnsemble(2, 4, 2, 2, [](auto m, auto i, auto, auto) {
        if (m == 0) return 9.0F;
        return i < 2 ? std::numeric_limits<float>::infinity() : 1.0F;
    });
    const auto d = prep::computeDistanceMatrix(e, 0.0F);
    EXPECT_DOUBLE_EQ(d.at(0, 1), 4.0);
}

TEST(Similarity, CancelThrowsAndProgressIsMonotonic) {
    // 200 000 points for 3 members: several blocks, so there are several progress reports.
    const auto e = test::analyticEnsemble(
        3, 100, 100, 20, [](auto m, auto i, auto, auto) { return static_cast<float>(m * i); });
    std::vector<double> fractions;
    prep::computeDistanceMatrix(e, 5.0F, {}, [&](double f) { fractions.push_back(f); });
    ASSERT_GE(fractions.size(), 3u);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_GE(fractions.front(), 0.0);
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);

    std::stop_source stop;
    int calls = 0;
    EXPECT_THROW(prep::computeDistanceMatrix(e, 5.0F, stop.get_token(),
                                             [&](double) {
                                                 if (++calls == 1) stop.request_stop();
                                             }),
                 data::Cancelled);
    // Blocks run on every core: those begun on other threads when the stop came still finish
    // and report; no other starts.
    EXPECT_GE(calls, 1);
    EXPECT_LE(calls, tbb::this_task_arena::max_concurrency())
        << "the step must stop at the blocks begun before the request";
    EXPECT_LT(static_cast<std::size_t>(calls), fractions.size());

    std::stop_source stopped;
    stopped.request_stop();
    EXPECT_THROW(prep::computeDistanceMatrix(e, 5.0F, stopped.get_token()), data::Cancelled);
}

TEST(Similarity, RejectsEmptyEnsemblesBadIsovaluesAndShortMembers) {
    data::Ensemble empty;
    EXPECT_THROW(prep::computeDistanceMatrix(empty, 1.0F), data::Error);
    auto e = test::analyticEnsemble(2, 2, 2, 2, [](auto, auto, auto, auto) { return 1.0F; });
    EXPECT_THROW(prep::computeDistanceMatrix(e, kNaN), data::Error);
    e.members[1].values.resize(5);
    try {
        prep::computeDistanceMatrix(e, 1.0F);
        ADD_FAILURE() << "a member with too few values must be rejected";
    } catch (const data::Error& error) {
        EXPECT_EQ(error.kind(), data::ErrorKind::InvalidArgument);
    }
}

TEST(Similarity, OneMemberGivesAZeroMatrix) {
    const auto e = test::analyticEnsemble(1, 2, 2, 2, [](auto, auto, auto, auto) { return 3.0F; });
    const auto d = prep::computeDistanceMatrix(e, 1.0F);
    ASSERT_EQ(d.size, 1u);
    EXPECT_EQ(d.at(0, 0), 0.0);
}

TEST(Similarity, TheDistancesToAReferenceComeWithTheMatrixFromOnePass) {
    // 6 members of 64 x 64 x 40 points with gaps (both block paths), a reference field with
    // gaps of its own, and a member that shares no valid point with it: the matrix is the one
    // computeDistanceMatrix gives, and each distance to the reference the plain loop's.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<float> value(0.0F, 60.0F);
    std::uniform_int_distribution<int> missing(0, 9);
    const std::size_t members = 6, points = 64 * 64 * 40;
    std::size_t point = 0;
    auto e = test::analyticEnsemble(members, 64, 64, 40, [&](std::size_t m, auto, auto, auto) {
        const std::size_t p = point++ % points;
        if (m == 5) return p < points / 2 ? value(rng) : kNaN;  // only where the reference is not
        return p < 60000 && missing(rng) == 0 ? kNaN : value(rng);
    });
    std::vector<float> reference(points);
    for (std::size_t p = 0; p < points; ++p) {
        reference[p] = p < points / 2 ? kNaN : (missing(rng) == 0 ? kNaN : value(rng));
    }
    const float isovalue = 30.0F;
    const prep::DistancesAndReference got =
        prep::computeDistancesAndReference(e, reference, isovalue);
    const prep::DistanceMatrix want = prep::computeDistanceMatrix(e, isovalue);
    ASSERT_EQ(got.matrix.size, members);
    EXPECT_EQ(got.matrix.pairsWithoutOverlap, want.pairsWithoutOverlap);
    for (std::size_t k = 0; k < want.values.size(); ++k) {
        EXPECT_NEAR(got.matrix.values[k], want.values[k], 1e-12 * want.values[k]) << k;
    }
    // The reference as one more member of a copy of the ensemble, measured point by point.
    data::Ensemble withReference = e;
    withReference.members.push_back(withReference.members.front());
    std::copy(reference.begin(), reference.end(), withReference.members.back().values.begin());
    ASSERT_EQ(got.toReference.size(), members);
    for (std::size_t m = 0; m + 1 < members; ++m) {
        const double expected = referenceDistance(withReference, isovalue, m, members);
        EXPECT_NEAR(got.toReference[m], expected, 1e-9 * expected) << "member " << m;
    }
    EXPECT_TRUE(std::isinf(got.toReference[5])) << "no point in common with the reference";
}

TEST(Similarity, TheDistancesToAReferenceRejectAReferenceOfAnotherSize) {
    const auto e = test::analyticEnsemble(
        3, 4, 3, 2, [](auto m, auto, auto, auto) { return static_cast<float>(m); });
    const std::vector<float> shorter(e.grid.pointCount() - 1, 1.0F);
    try {
        (void)prep::computeDistancesAndReference(e, shorter, 0.5F);
        FAIL() << "a reference of another size was accepted";
    } catch (const data::Error& error) {
        EXPECT_EQ(error.kind(), data::ErrorKind::InvalidArgument);
        EXPECT_NE(std::string(error.what()).find("23 values but the grid has 24"),
                  std::string::npos)
            << error.what();
    }
}

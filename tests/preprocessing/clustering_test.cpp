#include "preprocessing/clustering.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "data/demo_ensemble.h"
#include "data/error.h"
#include "fixtures.h"
#include "preprocessing/similarity.h"

using namespace ensil;

namespace {

using Row = std::array<double, 4>;  // a, b, height, size, as in SciPy's linkage matrix

prep::DistanceMatrix matrixFromPoints(const std::vector<std::array<double, 2>>& points) {
    prep::DistanceMatrix d;
    d.size = points.size();
    d.values.resize(d.size * d.size);
    for (std::size_t i = 0; i < d.size; ++i) {
        for (std::size_t j = 0; j < d.size; ++j) {
            const double dx = points[i][0] - points[j][0], dy = points[i][1] - points[j][1];
            d.values[i * d.size + j] = std::sqrt(dx * dx + dy * dy);
        }
    }
    return d;
}

prep::DistanceMatrix matrixFromLine(const std::vector<double>& xs) {
    std::vector<std::array<double, 2>> points;
    for (const double x : xs) points.push_back({x, 0.0});
    return matrixFromPoints(points);
}

void expectTree(const prep::MergeTree& tree, const std::vector<Row>& expected) {
    ASSERT_EQ(tree.merges.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
        const prep::Merge& m = tree.merges[k];
        EXPECT_EQ(m.a, static_cast<int>(expected[k][0])) << "merge " << k;
        EXPECT_EQ(m.b, static_cast<int>(expected[k][1])) << "merge " << k;
        if (std::isinf(expected[k][2])) {
            EXPECT_EQ(m.height, expected[k][2]) << "merge " << k;
        } else {
            EXPECT_NEAR(m.height, expected[k][2], 1e-12 * expected[k][2]) << "merge " << k;
        }
        EXPECT_EQ(m.size, static_cast<int>(expected[k][3])) << "merge " << k;
    }
}

prep::MergeTree cluster(const prep::DistanceMatrix& d, prep::Linkage linkage) {
    return prep::clusterMembers(d, linkage);
}

constexpr std::array kLinkages{prep::Linkage::Average, prep::Linkage::Single,
                               prep::Linkage::Complete, prep::Linkage::Ward};

}  // namespace

// Points 0, 4, 6, 10, 11 (members 0..4); no ties except the one noted for single linkage.
// Every linkage first merges 10-11 (d 1, cluster 5), then 4-6 (d 2, cluster 6). Then:
//  single:   d(0,6) = min(4,6) = 4, d(5,6) = min(|6-10|, ...) = 4, d(0,5) = 10: a tie at 4,
//            (0,6) beats (5,6) -> cluster 7 = {0,4,6} at 4; d(5,7) = min(10, 4) = 4.
//  complete: d(0,6) = 6, d(5,6) = |4-11| = 7, d(0,5) = 11 -> 7 at 6; d(5,7) = 11.
//  average:  d(0,6) = (4+6)/2 = 5, d(5,6) = (6+7+4+5)/4 = 5.5, d(0,5) = 10.5 -> 7 at 5;
//            d(5,7) = (1*10.5 + 2*5.5)/3 = 43/6 (the mean of all six member distances).
//  ward:     on a line, Ward's update gives sqrt(2|A||B|/(|A|+|B|)) |mean A - mean B|:
//            d(0,6) = sqrt(4/3) * 5 = sqrt(100/3), d(5,6) = sqrt(2) * 5.5 = sqrt(60.5),
//            d(0,5) = sqrt(4/3) * 10.5 = sqrt(147) -> 7 at sqrt(100/3);
//            d(5,7) = sqrt(12/5) * |10/3 - 10.5| = 43/sqrt(15). By the update formula:
//            sqrt(((2+1) 147 + (2+2) 60.5 - 2 (100/3)) / 5) = sqrt(1849/15), the same.
// SciPy 1.10 gives these four matrices too.
TEST(Clustering, HandComputedLinkageMatricesForPointsOnALine) {
    const auto d = matrixFromLine({0, 4, 6, 10, 11});
    const Row first{3, 4, 1, 2}, second{1, 2, 2, 2};
    expectTree(cluster(d, prep::Linkage::Single), {first, second, {0, 6, 4, 3}, {5, 7, 4, 5}});
    expectTree(cluster(d, prep::Linkage::Complete), {first, second, {0, 6, 6, 3}, {5, 7, 11, 5}});
    expectTree(cluster(d, prep::Linkage::Average),
               {first, second, {0, 6, 5, 3}, {5, 7, 43.0 / 6.0, 5}});
    expectTree(cluster(d, prep::Linkage::Ward),
               {first, second, {0, 6, std::sqrt(100.0 / 3.0), 3}, {5, 7, 43 / std::sqrt(15.0), 5}});
}

// Points 0, 2, 5, 9, 14: the linkages build different trees. All first merge 0-2 (d 2, id 5).
//  single:   d(5,2) = 3 < d(2,3) = 4 -> 6 = {0,2,5} at 3; then 9 joins at 4, 14 at 5 (a chain).
//  complete: d(5,2) = 5, d(2,3) = 4, d(3,4) = 5 -> 6 = {5,9} at 4; d(5,6) = 9, d(4,6) = 9,
//            d(5,4) = 14: a tie at 9 that (4,6) wins over (5,6) -> 7 at 9; (5,7) at 14.
//            (SciPy breaks this tie the other way.)
//  average:  d(5,2) = (5+3)/2 = 4 ties with d(2,3) = 4; (2,3) beats (2,5) -> 6 at 4;
//            d(5,6) = (5+9+3+7)/4 = 6, d(5,4) = (14+12)/2 = 13, d(6,4) = (9+5)/2 = 7 -> 7 at 6;
//            d(7,4) = (14+12+9+5)/4 = 10. (SciPy merges (2,5) at the tie instead.)
//  ward:     d(5,2) = sqrt(4/3) 4 > 4 = d(2,3) -> 6 = {5,9} at 4; d(4,6) = sqrt(4/3) 7 = 14/sqrt(3)
//            < d(5,6) = sqrt(2) 6 -> 7 = {5,9,14} at 14/sqrt(3);
//            d(5,7) = sqrt(12/5) |1 - 28/3| = sqrt(500/3).
TEST(Clustering, HandComputedTreesDifferBetweenLinkagesAndTiesFollowTheRule) {
    const auto d = matrixFromLine({0, 2, 5, 9, 14});
    const Row first{0, 1, 2, 2};
    expectTree(cluster(d, prep::Linkage::Single),
               {first, {2, 5, 3, 3}, {3, 6, 4, 4}, {4, 7, 5, 5}});
    expectTree(cluster(d, prep::Linkage::Complete),
               {first, {2, 3, 4, 2}, {4, 6, 9, 3}, {5, 7, 14, 5}});
    expectTree(cluster(d, prep::Linkage::Average),
               {first, {2, 3, 4, 2}, {5, 6, 6, 4}, {4, 7, 10, 5}});
    expectTree(
        cluster(d, prep::Linkage::Ward),
        {first, {2, 3, 4, 2}, {4, 6, 14 / std::sqrt(3.0), 3}, {5, 7, std::sqrt(500.0 / 3.0), 5}});
}

// Five evenly spaced points, single linkage: every merge is at distance 1.
//  step 0: pairs (0,1), (1,2), (2,3), (3,4) tie; (0,1) is smallest -> 5 = {0,1}.
//  step 1: candidates (2,5), (2,3), (3,4); (2,3) is smallest -> 6 = {2,3}.
//  step 2: candidates (5,6) and (4,6); (4,6) is smallest -> 7 = {2,3,4}.
//  step 3: (5,7).
// Equal distances between all four members of a second matrix: (0,1), then (2,3), then (4,5),
// the same for every linkage (Ward's update of equal distances is again that distance).
TEST(Clustering, TiesGoToTheSmallestPairOfIds) {
    expectTree(cluster(matrixFromLine({0, 1, 2, 3, 4}), prep::Linkage::Single),
               {{0, 1, 1, 2}, {2, 3, 1, 2}, {4, 6, 1, 3}, {5, 7, 1, 5}});
    prep::DistanceMatrix equal{4, std::vector<double>(16, 1.0), {}};
    for (std::size_t i = 0; i < 4; ++i) equal.values[i * 5] = 0.0;
    for (const auto linkage : kLinkages) {
        SCOPED_TRACE(prep::linkageName(linkage));
        expectTree(cluster(equal, linkage), {{0, 1, 1, 2}, {2, 3, 1, 2}, {4, 5, 1, 4}});
    }
}

// Twelve points in the plane, no tied distances. Expected rows from SciPy 1.10.1:
//   linkage(pdist(P), method) with P the points below (numpy default_rng(3), rounded).
TEST(Clustering, MatchesScipyOnRandomPoints) {
    const auto d = matrixFromPoints({{0.86, 2.37},
                                     {8.01, 5.82},
                                     {0.94, 4.33},
                                     {4.79, 1.60},
                                     {7.35, 1.14},
                                     {3.91, 5.17},
                                     {4.31, 5.87},
                                     {7.38, 9.56},
                                     {2.84, 6.49},
                                     {6.96, 2.93},
                                     {0.01, 9.73},
                                     {2.98, 3.14}});
    const std::map<prep::Linkage, std::vector<Row>> expected{
        {prep::Linkage::Average,
         {{5, 6, 0.80622577482985491, 2},
          {8, 12, 1.6473026666218551, 3},
          {4, 9, 1.8319934497699495, 2},
          {0, 2, 1.9616319736382766, 2},
          {11, 15, 2.3086099281944361, 3},
          {3, 14, 2.5730760312719667, 3},
          {13, 16, 3.5463272238471415, 6},
          {1, 7, 3.7926903380054644, 2},
          {17, 18, 5.0171153078753656, 9},
          {19, 20, 6.2296375686943328, 11},
          {10, 21, 7.5388107819506365, 12}}},
        {prep::Linkage::Single,
         {{5, 6, 0.80622577482985491, 2},
          {8, 12, 1.595399636454766, 3},
          {4, 9, 1.8319934497699495, 2},
          {0, 2, 1.9616319736382766, 2},
          {11, 13, 2.232890503361058, 4},
          {15, 16, 2.2555043781824056, 6},
          {3, 17, 2.3764890069175579, 7},
          {14, 18, 2.5451522547776979, 9},
          {1, 19, 3.0748333288163767, 10},
          {7, 20, 3.7926903380054644, 11},
          {10, 21, 4.3019181768136878, 12}}},
        {prep::Linkage::Complete,
         {{5, 6, 0.80622577482985491, 2},
          {8, 12, 1.6992056967889442, 3},
          {4, 9, 1.8319934497699495, 2},
          {0, 2, 1.9616319736382766, 2},
          {11, 15, 2.3617154782064667, 3},
          {3, 14, 2.600999807766236, 3},
          {1, 7, 3.7926903380054644, 2},
          {13, 16, 4.9145193050795921, 6},
          {17, 19, 7.1599022339694001, 9},
          {10, 18, 8.9043865594436102, 3},
          {20, 21, 11.298836223257686, 12}}},
        {prep::Linkage::Ward,
         {{5, 6, 0.80622577482985491, 2},
          {4, 9, 1.8319934497699495, 2},
          {8, 12, 1.8452822728966607, 3},
          {0, 2, 1.9616319736382766, 2},
          {3, 11, 2.3764890069175579, 2},
          {1, 7, 3.7926903380054644, 2},
          {15, 16, 4.4431126476829279, 4},
          {14, 18, 6.0214317629771807, 7},
          {13, 17, 8.0337569044625692, 4},
          {10, 19, 8.3551805999118223, 8},
          {20, 21, 11.189197171081281, 12}}},
    };
    for (const auto& [linkage, rows] : expected) {
        SCOPED_TRACE(prep::linkageName(linkage));
        expectTree(cluster(d, linkage), rows);
    }
}

// Complete linkage on 0, 2, 5, 9, 14 (see above): merges {0,1} -> 5, {2,3} -> 6, {4,6} -> 7,
// {5,7} -> 8. Leaf order: 8 = (5, 7) -> 5 = (0, 1) -> 0, 1; 7 = (4, 6) -> 4, then 6 -> 2, 3.
// k clusters keep the first 5 - k merges:
//  k=2: {0,1} {2,3,4}       -> leaf order meets {0,1} first: 0, then {4,2,3}: 1.
//  k=3: {0,1} {2,3} {4}     -> leaves 0 1 | 4 | 2 3: labels 0, 1 (member 4), 2 (members 2, 3).
//  k=4: {0,1} {2} {3} {4}   -> leaves 0 1 | 4 | 2 | 3: members 4, 2, 3 get 1, 2, 3.
//  k=5: every member alone, numbered along 0, 1, 4, 2, 3.
TEST(Clustering, LabelsForEveryKAreNumberedInLeafOrder) {
    const auto tree = cluster(matrixFromLine({0, 2, 5, 9, 14}), prep::Linkage::Complete);
    EXPECT_EQ(prep::leafOrder(tree), (std::vector<int>{0, 1, 4, 2, 3}));
    EXPECT_EQ(prep::clusterLabels(tree, 1), (std::vector<int>{0, 0, 0, 0, 0}));
    EXPECT_EQ(prep::clusterLabels(tree, 2), (std::vector<int>{0, 0, 1, 1, 1}));
    EXPECT_EQ(prep::clusterLabels(tree, 3), (std::vector<int>{0, 0, 2, 2, 1}));
    EXPECT_EQ(prep::clusterLabels(tree, 4), (std::vector<int>{0, 0, 2, 3, 1}));
    EXPECT_EQ(prep::clusterLabels(tree, 5), (std::vector<int>{0, 1, 3, 4, 2}));
    // Heights 2, 4, 9, 14: the cut lines lie midway.
    EXPECT_DOUBLE_EQ(prep::mergeHeightForClusters(tree, 5), 1.0);
    EXPECT_DOUBLE_EQ(prep::mergeHeightForClusters(tree, 4), 3.0);
    EXPECT_DOUBLE_EQ(prep::mergeHeightForClusters(tree, 3), 6.5);
    EXPECT_DOUBLE_EQ(prep::mergeHeightForClusters(tree, 2), 11.5);
    EXPECT_DOUBLE_EQ(prep::mergeHeightForClusters(tree, 1), 14.0);
}

TEST(Clustering, EveryCutIsContiguousInLeafOrderAndRefinesTheCoarserOne) {
    const auto d = matrixFromPoints({{0.86, 2.37},
                                     {8.01, 5.82},
                                     {0.94, 4.33},
                                     {4.79, 1.60},
                                     {7.35, 1.14},
                                     {3.91, 5.17},
                                     {4.31, 5.87},
                                     {7.38, 9.56},
                                     {2.84, 6.49},
                                     {6.96, 2.93},
                                     {0.01, 9.73},
                                     {2.98, 3.14}});
    for (const auto linkage : kLinkages) {
        SCOPED_TRACE(prep::linkageName(linkage));
        const auto tree = cluster(d, linkage);
        const std::vector<int> order = prep::leafOrder(tree);
        std::vector<int> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        std::vector<int> identity(12);
        std::iota(identity.begin(), identity.end(), 0);
        ASSERT_EQ(sorted, identity) << "leafOrder must be a permutation";
        std::vector<int> coarser(12, 0);
        for (int k = 1; k <= 12; ++k) {
            const std::vector<int> labels = prep::clusterLabels(tree, k);
            // Along the leaf order labels only step up by one: 0, 0, 1, 1, 1, 2, ...
            int previous = 0;
            for (const int leaf : order) {
                const int label = labels[static_cast<std::size_t>(leaf)];
                EXPECT_TRUE(label == previous || label == previous + 1) << "k=" << k;
                previous = label;
            }
            EXPECT_EQ(previous, k - 1) << "k=" << k;
            // Members together at k were together at k - 1.
            for (std::size_t i = 0; i < 12; ++i) {
                for (std::size_t j = 0; j < 12; ++j) {
                    if (labels[i] == labels[j]) {
                        EXPECT_EQ(coarser[i], coarser[j]) << "k=" << k;
                    }
                }
            }
            coarser = labels;
        }
    }
}

// Points 0, 1, 2, 10, 11, 13, single linkage, k = 2: clusters {0,1,2} (label 0: member 2 is
// the first leaf) and {3,4,5}. Medoid of {0,1,2} is 1 (sums 3, 2, 3); 0 and 2 tie at 1, the
// smaller index goes first: 1, 0, 2. Medoid of {10,11,13} is 4 (sums 4, 3, 5); then 3 (d 1),
// then 5: 4, 3, 5.
TEST(Clustering, AnimationOrderGroupsClustersAndChainsFromTheMedoid) {
    const auto d = matrixFromLine({0, 1, 2, 10, 11, 13});
    const auto tree = cluster(d, prep::Linkage::Single);
    EXPECT_EQ(prep::leafOrder(tree), (std::vector<int>{2, 0, 1, 5, 3, 4}));
    EXPECT_EQ(prep::animationOrder(tree, d, 2), (std::vector<int>{1, 0, 2, 4, 3, 5}));
    // One cluster: members 2 and 3 tie as medoid (sums 31); 2 wins, then 1, 0, 3, 4, 5.
    EXPECT_EQ(prep::animationOrder(tree, d, 1), (std::vector<int>{2, 1, 0, 3, 4, 5}));
}

TEST(Clustering, LinkageNamesRoundTripAndUnknownNamesListTheChoices) {
    for (const auto linkage : kLinkages) {
        EXPECT_EQ(prep::parseLinkage(prep::linkageName(linkage)), linkage);
    }
    EXPECT_EQ(prep::parseLinkage("Ward"), prep::Linkage::Ward);
    EXPECT_EQ(prep::linkageName(prep::Linkage::Average), "average");
    try {
        prep::parseLinkage("centroid");
        ADD_FAILURE() << "unknown linkage accepted";
    } catch (const data::Error& error) {
        EXPECT_EQ(error.kind(), data::ErrorKind::InvalidArgument);
        EXPECT_EQ(error.choices(),
                  (std::vector<std::string>{"average", "single", "complete", "ward"}));
    }
}

TEST(Clustering, RejectsBadMatricesAndClusterCounts) {
    const auto expectInvalid = [](auto&& call) {
        try {
            call();
            ADD_FAILURE() << "accepted";
        } catch (const data::Error& error) {
            EXPECT_EQ(error.kind(), data::ErrorKind::InvalidArgument);
        }
    };
    expectInvalid([] { prep::clusterMembers(prep::DistanceMatrix{}); });
    expectInvalid([] { prep::clusterMembers(prep::DistanceMatrix{2, {0, 1, 1}, {}}); });
    expectInvalid([] { prep::clusterMembers(prep::DistanceMatrix{2, {0, 1, 2, 0}, {}}); });
    expectInvalid([] { prep::clusterMembers(prep::DistanceMatrix{2, {0, -1, -1, 0}, {}}); });
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expectInvalid([&] { prep::clusterMembers(prep::DistanceMatrix{2, {0, nan, nan, 0}, {}}); });
    const auto d = matrixFromLine({0, 1, 5});
    const auto tree = cluster(d, prep::Linkage::Average);
    expectInvalid([&] { prep::clusterLabels(tree, 0); });
    expectInvalid([&] { prep::clusterLabels(tree, 4); });
    expectInvalid([&] { prep::mergeHeightForClusters(tree, 0); });
    expectInvalid([&] { prep::animationOrder(tree, d, 4); });
    expectInvalid([&] { prep::animationOrder(tree, matrixFromLine({0, 1}), 2); });
}

TEST(Clustering, OneMemberAndInfiniteDistances) {
    const auto single = cluster(prep::DistanceMatrix{1, {0.0}, {}}, prep::Linkage::Ward);
    EXPECT_EQ(single.memberCount, 1);
    EXPECT_TRUE(single.merges.empty());
    EXPECT_EQ(prep::clusterLabels(single, 1), std::vector<int>{0});
    EXPECT_EQ(prep::leafOrder(single), std::vector<int>{0});
    EXPECT_EQ(prep::mergeHeightForClusters(single, 1), 0.0);

    // Members 0 and 1 share no valid point with member 2: it joins last, at infinity.
    const double inf = std::numeric_limits<double>::infinity();
    const prep::DistanceMatrix d{3, {0, 1, inf, 1, 0, inf, inf, inf, 0}, {}};
    for (const auto linkage : kLinkages) {
        SCOPED_TRACE(prep::linkageName(linkage));
        expectTree(cluster(d, linkage), {{0, 1, 1, 2}, {2, 3, inf, 3}});
    }
}

TEST(Clustering, CancelThrowsAndProgressIsMonotonic) {
    std::vector<double> xs(40);
    std::iota(xs.begin(), xs.end(), 0.0);
    for (double& x : xs) x = x * x;  // no ties
    const auto d = matrixFromLine(xs);
    std::vector<double> fractions;
    prep::clusterMembers(d, prep::Linkage::Average, {}, [&](double f) { fractions.push_back(f); });
    ASSERT_GE(fractions.size(), 39u);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);

    std::stop_source stop;
    int calls = 0;
    EXPECT_THROW(prep::clusterMembers(d, prep::Linkage::Average, stop.get_token(),
                                      [&](double) {
                                          if (++calls == 3) stop.request_stop();
                                      }),
                 data::Cancelled);
    EXPECT_EQ(calls, 3) << "the step must stop at the next merge after the request";
}

// Members 0..4: a Gaussian blob left of centre, 5..9 the same blob right of centre, each
// member shifted by half a cell from the one before. Every linkage splits them at k = 2.
TEST(Clustering, DriftingBlobsSplitIntoTheirTwoGroups) {
    const auto e = test::analyticEnsemble(10, 40, 16, 8, [](auto m, auto i, auto j, auto k) {
        const double cx = (m < 5 ? 9.0 : 28.0) + 0.5 * static_cast<double>(m % 5);
        const double dx = static_cast<double>(i) - cx, dy = static_cast<double>(j) - 7.5,
                     dz = static_cast<double>(k) - 3.5;
        return static_cast<float>(100.0 * std::exp(-(dx * dx + dy * dy + dz * dz) / 18.0));
    });
    const auto d = prep::computeDistanceMatrix(e, 50.0F);
    for (const auto linkage : kLinkages) {
        SCOPED_TRACE(prep::linkageName(linkage));
        const auto tree = cluster(d, linkage);
        const std::vector<int> labels = prep::clusterLabels(tree, 2);
        // Which blob gets label 0 depends on the leaf order; the split itself must not.
        const int left = labels[0];
        EXPECT_EQ(labels, (left == 0 ? std::vector<int>{0, 0, 0, 0, 0, 1, 1, 1, 1, 1}
                                     : std::vector<int>{1, 1, 1, 1, 1, 0, 0, 0, 0, 0}));
        const auto order = prep::animationOrder(tree, d, 2);
        const int firstBlob = left == 0 ? 0 : 5;
        for (std::size_t x = 0; x < 10; ++x) {
            EXPECT_EQ(order[x] / 5, (x < 5 ? firstBlob : 5 - firstBlob) / 5) << "position " << x;
        }
        // Within a blob the chain starts at the middle member of the drift.
        EXPECT_EQ(order[0], firstBlob + 2);
        EXPECT_EQ(order[5], 5 - firstBlob + 2);
    }
}

namespace {

double pairs(double n) { return n * (n - 1.0) / 2.0; }

// Adjusted Rand index (Hubert and Arabie 1985) between two labelings: 1 for identical
// partitions, 0 in expectation for a random one.
double adjustedRandIndex(const std::vector<int>& x, const std::vector<int>& y) {
    std::map<std::pair<int, int>, double> both;
    std::map<int, double> inX, inY;
    for (std::size_t i = 0; i < x.size(); ++i) {
        both[{x[i], y[i]}] += 1.0;
        inX[x[i]] += 1.0;
        inY[y[i]] += 1.0;
    }
    double index = 0.0, sumX = 0.0, sumY = 0.0;
    for (const auto& entry : both) index += pairs(entry.second);
    for (const auto& entry : inX) sumX += pairs(entry.second);
    for (const auto& entry : inY) sumY += pairs(entry.second);
    const double expected = sumX * sumY / pairs(static_cast<double>(x.size()));
    return (index - expected) / (0.5 * (sumX + sumY) - expected);
}

}  // namespace

TEST(Clustering, DemoEnsembleRegimesAreFoundAndTheOutlierStandsAlone) {
    const auto demo =
        data::makeDemoEnsemble({.members = 30, .nx = 64, .ny = 32, .nz = 8, .seed = 11});
    const auto outlier = static_cast<std::size_t>(
        std::find(demo.regimes.begin(), demo.regimes.end(), data::DemoRegime::Outlier) -
        demo.regimes.begin());
    ASSERT_EQ(std::count(demo.regimes.begin(), demo.regimes.end(), data::DemoRegime::Outlier), 1);
    const auto d = prep::computeDistanceMatrix(demo.ensemble, 30.0F);
    const auto tree = cluster(d, prep::Linkage::Average);
    int singletonAt = 0;
    for (int k = 2; k <= 6 && singletonAt == 0; ++k) {
        const auto labels = prep::clusterLabels(tree, k);
        if (std::count(labels.begin(), labels.end(), labels[outlier]) == 1) singletonAt = k;
    }
    EXPECT_GT(singletonAt, 0) << "the outlier must be a cluster of its own at some k <= 6";
    std::vector<int> regimes;
    for (const auto regime : demo.regimes) regimes.push_back(static_cast<int>(regime));
    ASSERT_DOUBLE_EQ(adjustedRandIndex(regimes, regimes), 1.0);
    const double ari3 = adjustedRandIndex(regimes, prep::clusterLabels(tree, 3));
    const double ari4 = adjustedRandIndex(regimes, prep::clusterLabels(tree, 4));
    // Seed 11 gives 1.0 at k = 4 (regimes recovered exactly) and 0.54 at k = 3.
    EXPECT_GT(std::max(ari3, ari4), 0.8)
        << "adjusted Rand index k=3 " << ari3 << ", k=4 " << ari4 << "; chance level is 0";
}

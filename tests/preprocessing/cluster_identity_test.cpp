// Stable cluster identity: the k-rule on the demo's tree for k = 2..12, changes of k from the
// identities shown, and matching across a change of isovalue with the largest overlap.
#include "preprocessing/cluster_identity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>

#include "data/demo_ensemble.h"
#include "preprocessing/similarity.h"

using namespace ensil;

namespace {
prep::MergeTree demoTree(float isovalue) {
    const data::DemoEnsembleParams params{.members = 30, .nx = 48, .ny = 24, .nz = 8, .seed = 3};
    const data::Ensemble e = data::makeDemoEnsemble(params).ensemble;
    return prep::clusterMembers(prep::computeDistanceMatrix(e, isovalue));
}

}  // namespace

TEST(ClusterIdentity, EachSplitKeepsTheColourOnItsLargerPartForKFrom2To12) {
    const prep::MergeTree tree = demoTree(30.0F);
    std::vector<int> before =
        prep::memberIdentities(prep::clusterLabels(tree, 1), prep::identitiesFromTree(tree, 1));
    for (int k = 2; k <= 12; ++k) {
        const std::vector<int> labels = prep::clusterLabels(tree, k);
        const std::vector<int> ids = prep::identitiesFromTree(tree, k);
        // k clusters carry the identities 0..k-1, each once.
        std::vector<int> sorted = ids;
        std::sort(sorted.begin(), sorted.end());
        std::vector<int> expected(static_cast<std::size_t>(k));
        std::iota(expected.begin(), expected.end(), 0);
        EXPECT_EQ(sorted, expected) << "k = " << k;
        // Exactly the members of the split's smaller part changed colour, to the new one.
        const std::vector<int> after = prep::memberIdentities(labels, ids);
        std::set<int> changedTo, changedFrom;
        int changed = 0;
        for (std::size_t m = 0; m < after.size(); ++m) {
            if (after[m] == before[m]) continue;
            ++changed;
            changedTo.insert(after[m]);
            changedFrom.insert(before[m]);
        }
        ASSERT_EQ(changedTo, std::set<int>{k - 1}) << "k = " << k;
        ASSERT_EQ(changedFrom.size(), 1U);
        const int kept = *changedFrom.begin();
        const int keptSize = static_cast<int>(std::count(after.begin(), after.end(), kept));
        EXPECT_GE(keptSize, changed) << "the larger part keeps its colour (k = " << k << ")";
        // It is a pure function of the tree and k: walking there step by step agrees.
        EXPECT_EQ(prep::followTree(tree, k - 1, prep::identitiesFromTree(tree, k - 1), k), ids);
        before = after;
    }
}

TEST(ClusterIdentity, GoingDownMergesIntoTheLargerPartsColour) {
    const prep::MergeTree tree = demoTree(30.0F);
    const std::vector<int> five = prep::identitiesFromTree(tree, 5);
    const std::vector<int> three = prep::followTree(tree, 5, five, 3);
    EXPECT_EQ(three, prep::identitiesFromTree(tree, 3)) << "down the tree undoes the splits up it";
}

TEST(ClusterIdentity, ANewTreeTakesThePartnersWithTheLargestOverlap) {
    const prep::MergeTree first = demoTree(30.0F);
    const prep::MergeTree second = demoTree(25.0F);
    const int k = 5;
    const std::vector<int> previous =
        prep::memberIdentities(prep::clusterLabels(first, k), prep::identitiesFromTree(first, k));
    const std::vector<int> labels = prep::clusterLabels(second, k);
    const std::vector<int> ids = prep::matchIdentities(labels, k, previous);
    const auto overlapOf = [&](const std::vector<int>& assignment) {
        int total = 0;
        for (std::size_t m = 0; m < labels.size(); ++m) {
            if (assignment[static_cast<std::size_t>(labels[m])] == previous[m]) ++total;
        }
        return total;
    };
    // No other assignment of the 5 identities keeps more members in their colour.
    std::vector<int> permutation{0, 1, 2, 3, 4};
    int best = 0;
    do {
        best = std::max(best, overlapOf(permutation));
    } while (std::next_permutation(permutation.begin(), permutation.end()));
    EXPECT_EQ(overlapOf(ids), best);
    std::vector<int> sorted = ids;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, permutation) << "each identity once";
}

TEST(ClusterIdentity, UnmatchedClustersTakeTheLowestFreeIdentities) {
    // Previously two clusters, identities 3 and 5; now three: one new cluster shares nothing.
    const std::vector<int> previous{3, 3, 5, 5, -1, -1};
    const std::vector<int> labels{0, 0, 1, 1, 2, 2};
    EXPECT_EQ(prep::matchIdentities(labels, 3, previous), (std::vector<int>{3, 5, 0}));
}

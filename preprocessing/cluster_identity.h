// Stable cluster identity (METHODS.md section 8): the colour and number each cluster keeps
// while the user changes the number of clusters, the linkage or the isovalue, so that a
// colour keeps its meaning. An identity is a small whole number (0, 1, 2, ...): the palette
// colour and, plus one, the number the legend shows. Identities are given per cluster label
// of clusterLabels(tree, k). Pure functions; any thread.
//
// - From nothing: walk the tree from k = 1 (identity 0) upward; each split keeps the identity
//   on its larger part (ties: the part holding the lowest member index), the other part takes
//   the lowest free identity. A pure function of the tree and k, so `ensil preprocess` and the
//   workbench agree. For this walk the identities of k clusters are 0..k-1.
// - A change of k on the same tree: from the identities shown, split as above, or merge (the
//   merged cluster keeps the identity of its larger part).
// - A new tree (isovalue, linkage): the new clusters are matched to the previous identities by
//   shared members, with the largest total overlap (Hungarian assignment); a matched cluster
//   takes its partner's identity, the others the lowest free ones.
#pragma once

#include <vector>

#include "preprocessing/clustering.h"

namespace ensil::prep {

// Throws data::Error(InvalidArgument) for k outside 1..N.
std::vector<int> identitiesFromTree(const MergeTree& tree, int k);

// `identities` belong to the cut at `fromK`; the result to the cut at `toK`.
std::vector<int> followTree(const MergeTree& tree, int fromK, const std::vector<int>& identities,
                            int toK);

// `labels` (k clusters, one label per member) matched to each member's previous identity
// (`previous`, one per member, -1 for a member that had none).
std::vector<int> matchIdentities(const std::vector<int>& labels, int k,
                                 const std::vector<int>& previous);

// Per member: the identity of its cluster.
std::vector<int> memberIdentities(const std::vector<int>& labels,
                                  const std::vector<int>& identities);

}  // namespace ensil::prep

// Agglomerative hierarchical clustering of ensemble members (METHODS.md sections 8 and 13):
// the full merge tree is kept, so any number of clusters 1..N is available instantly for
// coloring, showing and hiding clusters, the dendrogram, and the animation order.
// Pure functions on plain values; run on any thread.
//
// Conventions (those of SciPy's linkage matrix, so results can be checked against
// scipy.cluster.hierarchy.linkage(squareform(D), method)):
//  - Cluster ids 0..N-1 are the members; merge k (0-based) creates cluster N + k.
//  - Merge k joins clusters a < b at distance `height` into a cluster of `size` members.
//  - Merges are listed in the order they happen; heights never decrease (all four linkages are
//    monotone).
//  - Ties: among pairs at exactly the same distance, the pair with the smallest
//    (min id, max id), compared lexicographically, merges first. So singletons merge before
//    clusters made later, and the result depends only on the distances, never on scan order.
//    (SciPy's own tie order can differ; its heights cannot.)
#pragma once

#include <stop_token>
#include <string>
#include <vector>

#include "data/job.h"
#include "preprocessing/similarity.h"

namespace ensil::prep {

// How the distance between two clusters follows from member distances (Lance-Williams updates,
// exactly as SciPy computes them on the given distances):
//  - Average:  d(u, s+t) = (|s| d(u,s) + |t| d(u,t)) / (|s| + |t|)  (mean of member distances)
//  - Single:   d(u, s+t) = min(d(u,s), d(u,t))
//  - Complete: d(u, s+t) = max(d(u,s), d(u,t))
//  - Ward:     d(u, s+t) = sqrt(((|u|+|s|) d(u,s)^2 + (|u|+|t|) d(u,t)^2 - |u| d(s,t)^2)
//                               / (|u|+|s|+|t|))
enum class Linkage { Average, Single, Complete, Ward };

// "average", "single", "complete", "ward" (any case). Throws data::Error(InvalidArgument), with
// the valid names as choices, for anything else.
Linkage parseLinkage(const std::string& name);
// The lower-case name parseLinkage accepts.
std::string linkageName(Linkage linkage);

struct Merge {
    int a = 0;            // the smaller id of the two clusters merged
    int b = 0;            // the larger id
    double height = 0.0;  // their linkage distance when merged
    int size = 0;         // members in the new cluster
};

struct MergeTree {
    int memberCount = 0;        // N
    std::vector<Merge> merges;  // N - 1 merges; merge k creates cluster N + k
};

// Clusters the members whose distances are given (N >= 1). O(N^2) memory, O(N^3) time: about
// 1 ms for N = 200 in an optimised build. Distances may be +infinity (members with no valid
// point in common); such pairs merge last, at infinite height.
// Throws data::Cancelled if stop is requested, data::Error(InvalidArgument) for an empty,
// non-square or asymmetric matrix, or for negative or NaN distances.
MergeTree clusterMembers(const DistanceMatrix& distances, Linkage linkage = Linkage::Average,
                         const std::stop_token& stop = {}, const data::Progress& progress = {});

// The members in dendrogram order: depth-first through the tree from the root, the child `a`
// of each merge before `b`. Every cluster of every cut is a contiguous run of this order.
std::vector<int> leafOrder(const MergeTree& tree);

// The cluster of each member when the tree is cut into k clusters (the last k - 1 merges
// undone), for k in 1..N. Labels are 0..k-1, numbered in leafOrder: the cluster of the first
// leaf is 0, the next cluster met along the leaf order is 1, and so on. O(N).
// Throws data::Error(InvalidArgument) for k outside 1..N.
std::vector<int> clusterLabels(const MergeTree& tree, int k);

// The height of the dendrogram's cut line for k clusters: midway between the last merge kept
// and the first merge undone (half the first merge height for k = N, the root height for
// k = 1, 0 when N = 1). With tied heights the line cannot separate the tied merges.
// Throws data::Error(InvalidArgument) for k outside 1..N.
double mergeHeightForClusters(const MergeTree& tree, int k);

// The order the animation shows members in (METHODS.md section 13): clusters by label
// (clusterLabels(tree, k)), and within a cluster a nearest-neighbour chain: it starts at the
// cluster's medoid (the member with the smallest sum of distances to the others in its
// cluster) and goes on to the nearest member not shown yet. Ties pick the smaller member index.
// Throws data::Error(InvalidArgument) for k outside 1..N or a matrix of another size.
std::vector<int> animationOrder(const MergeTree& tree, const DistanceMatrix& distances, int k);

}  // namespace ensil::prep

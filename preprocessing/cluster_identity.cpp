#include "preprocessing/cluster_identity.h"

#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "data/error.h"

namespace ensil::prep {
namespace {

// The tree's nodes: leaves 0..N-1, merge r makes node N + r. For each node its member count
// and lowest member index (the tie-break of the split rule).
struct Nodes {
    int n = 0;
    std::vector<int> a, b;  // children of node N + r
    std::vector<int> size, lowest;

    explicit Nodes(const MergeTree& tree) : n(tree.memberCount) {
        const auto total = static_cast<std::size_t>(std::max(2 * n - 1, 0));
        size.assign(total, 1);
        lowest.resize(total);
        for (int m = 0; m < n; ++m) lowest[static_cast<std::size_t>(m)] = m;
        for (std::size_t r = 0; r < tree.merges.size(); ++r) {
            const Merge& merge = tree.merges[r];
            a.push_back(merge.a);
            b.push_back(merge.b);
            const auto node = static_cast<std::size_t>(n) + r;
            size[node] =
                size[static_cast<std::size_t>(merge.a)] + size[static_cast<std::size_t>(merge.b)];
            lowest[node] = std::min(lowest[static_cast<std::size_t>(merge.a)],
                                    lowest[static_cast<std::size_t>(merge.b)]);
        }
    }
    // The child that keeps its parent's identity.
    [[nodiscard]] bool firstIsLarger(int x, int y) const {
        const auto i = static_cast<std::size_t>(x), j = static_cast<std::size_t>(y);
        return size[i] != size[j] ? size[i] > size[j] : lowest[i] < lowest[j];
    }
    // The node that going from k to k + 1 clusters splits (splitAt(1) is the root).
    [[nodiscard]] int splitAt(int k) const { return n + (n - 1 - k); }
    [[nodiscard]] int root() const { return n == 1 ? 0 : splitAt(1); }
    [[nodiscard]] int leafOf(int node) const { return lowest[static_cast<std::size_t>(node)]; }
};

int lowestFree(const std::map<int, int>& identityOfNode) {
    std::set<int> used;
    for (const auto& [node, identity] : identityOfNode) used.insert(identity);
    int free = 0;
    while (used.contains(free)) ++free;
    return free;
}

// The current clusters (nodes) of the cut at k with their identities, from identities per
// label of clusterLabels(tree, k).
std::map<int, int> nodesOfCut(const Nodes& nodes, const MergeTree& tree, int k,
                              const std::vector<int>& identities) {
    std::set<int> cut{nodes.root()};
    for (int j = 1; j < k; ++j) {
        const int node = nodes.splitAt(j);
        const auto r = static_cast<std::size_t>(node - nodes.n);
        cut.erase(node);
        cut.insert(nodes.a[r]);
        cut.insert(nodes.b[r]);
    }
    const std::vector<int> labels = clusterLabels(tree, k);
    std::map<int, int> identityOfNode;
    for (const int node : cut) {
        const int label = labels[static_cast<std::size_t>(nodes.leafOf(node))];
        identityOfNode[node] = identities.at(static_cast<std::size_t>(label));
    }
    return identityOfNode;
}

std::vector<int> perLabel(const Nodes& nodes, const MergeTree& tree, int k,
                          const std::map<int, int>& identityOfNode) {
    const std::vector<int> labels = clusterLabels(tree, k);
    std::vector<int> identities(static_cast<std::size_t>(k), -1);
    for (const auto& [node, identity] : identityOfNode) {
        identities[static_cast<std::size_t>(labels[static_cast<std::size_t>(nodes.leafOf(node))])] =
            identity;
    }
    return identities;
}

// Maximum-weight assignment of rows to columns of a square matrix (Kuhn-Munkres, O(n^3), on
// costs -weight). Written here: k is at most a few dozen, and no Debian package offers it
// without a heavy dependency. Returns the column of each row.
std::vector<int> assignMaximum(const std::vector<std::vector<double>>& weight) {
    const int n = static_cast<int>(weight.size());
    const double inf = std::numeric_limits<double>::infinity();
    // 1-based potentials u (rows), v (columns); p[j]: the row matched to column j; way: path.
    std::vector<double> u(static_cast<std::size_t>(n) + 1), v(static_cast<std::size_t>(n) + 1);
    std::vector<int> p(static_cast<std::size_t>(n) + 1), way(static_cast<std::size_t>(n) + 1);
    const auto cost = [&](int i, int j) {
        return -weight[static_cast<std::size_t>(i - 1)][static_cast<std::size_t>(j - 1)];
    };
    for (int i = 1; i <= n; ++i) {
        p[0] = i;
        int j0 = 0;
        std::vector<double> minv(static_cast<std::size_t>(n) + 1, inf);
        std::vector<bool> used(static_cast<std::size_t>(n) + 1, false);
        do {
            used[static_cast<std::size_t>(j0)] = true;
            const int i0 = p[static_cast<std::size_t>(j0)];
            double delta = inf;
            int j1 = 0;
            for (int j = 1; j <= n; ++j) {
                if (used[static_cast<std::size_t>(j)]) continue;
                const double cur =
                    cost(i0, j) - u[static_cast<std::size_t>(i0)] - v[static_cast<std::size_t>(j)];
                if (cur < minv[static_cast<std::size_t>(j)]) {
                    minv[static_cast<std::size_t>(j)] = cur;
                    way[static_cast<std::size_t>(j)] = j0;
                }
                if (minv[static_cast<std::size_t>(j)] < delta) {
                    delta = minv[static_cast<std::size_t>(j)];
                    j1 = j;
                }
            }
            for (int j = 0; j <= n; ++j) {
                if (used[static_cast<std::size_t>(j)]) {
                    u[static_cast<std::size_t>(p[static_cast<std::size_t>(j)])] += delta;
                    v[static_cast<std::size_t>(j)] -= delta;
                } else {
                    minv[static_cast<std::size_t>(j)] -= delta;
                }
            }
            j0 = j1;
        } while (p[static_cast<std::size_t>(j0)] != 0);
        do {
            const int j1 = way[static_cast<std::size_t>(j0)];
            p[static_cast<std::size_t>(j0)] = p[static_cast<std::size_t>(j1)];
            j0 = j1;
        } while (j0 != 0);
    }
    std::vector<int> columnOfRow(static_cast<std::size_t>(n), -1);
    for (int j = 1; j <= n; ++j) {
        if (p[static_cast<std::size_t>(j)] > 0) {
            columnOfRow[static_cast<std::size_t>(p[static_cast<std::size_t>(j)] - 1)] = j - 1;
        }
    }
    return columnOfRow;
}

}  // namespace

std::vector<int> identitiesFromTree(const MergeTree& tree, int k) {
    (void)clusterLabels(tree, k);  // validates k
    return followTree(tree, 1, {0}, k);
}

std::vector<int> followTree(const MergeTree& tree, int fromK, const std::vector<int>& identities,
                            int toK) {
    const Nodes nodes(tree);
    std::map<int, int> cut = nodesOfCut(nodes, tree, fromK, identities);
    for (int k = fromK; k < toK; ++k) {  // splits
        const int node = nodes.splitAt(k);
        const auto r = static_cast<std::size_t>(node - nodes.n);
        const int identity = cut.at(node);
        cut.erase(node);
        const bool aKeeps = nodes.firstIsLarger(nodes.a[r], nodes.b[r]);
        const int keeper = aKeeps ? nodes.a[r] : nodes.b[r];
        const int other = aKeeps ? nodes.b[r] : nodes.a[r];
        cut[keeper] = identity;
        cut[other] = lowestFree(cut);
    }
    for (int k = fromK; k > toK; --k) {  // merges
        const int node = nodes.splitAt(k - 1);
        const auto r = static_cast<std::size_t>(node - nodes.n);
        const int larger = nodes.firstIsLarger(nodes.a[r], nodes.b[r]) ? nodes.a[r] : nodes.b[r];
        const int identity = cut.at(larger);
        cut.erase(nodes.a[r]);
        cut.erase(nodes.b[r]);
        cut[node] = identity;
    }
    return perLabel(nodes, tree, toK, cut);
}

std::vector<int> matchIdentities(const std::vector<int>& labels, int k,
                                 const std::vector<int>& previous) {
    if (labels.size() != previous.size()) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "matching clusters needs one previous identity per member");
    }
    // Rows: the previous identities present; columns: the new labels; weights: shared members.
    std::vector<int> old;
    for (const int id : previous) {
        if (id >= 0 && std::find(old.begin(), old.end(), id) == old.end()) old.push_back(id);
    }
    std::sort(old.begin(), old.end());
    const std::size_t size = std::max(old.size(), static_cast<std::size_t>(k));
    std::vector<std::vector<double>> overlap(size, std::vector<double>(size, 0.0));
    for (std::size_t m = 0; m < labels.size(); ++m) {
        if (previous[m] < 0) continue;
        const auto row =
            static_cast<std::size_t>(std::find(old.begin(), old.end(), previous[m]) - old.begin());
        overlap[row][static_cast<std::size_t>(labels[m])] += 1.0;
    }
    const std::vector<int> columnOfRow = assignMaximum(overlap);
    std::vector<int> identities(static_cast<std::size_t>(k), -1);
    std::set<int> used;
    for (std::size_t row = 0; row < old.size(); ++row) {
        const int column = columnOfRow[row];
        if (column < 0 || column >= k || overlap[row][static_cast<std::size_t>(column)] == 0.0) {
            continue;  // shares no member: no partner
        }
        identities[static_cast<std::size_t>(column)] = old[row];
        used.insert(old[row]);
    }
    int free = 0;
    for (int& identity : identities) {
        if (identity >= 0) continue;
        while (used.contains(free)) ++free;
        identity = free;
        used.insert(free);
    }
    return identities;
}

std::vector<int> memberIdentities(const std::vector<int>& labels,
                                  const std::vector<int>& identities) {
    std::vector<int> out(labels.size(), -1);
    for (std::size_t m = 0; m < labels.size(); ++m) {
        if (labels[m] >= 0 && static_cast<std::size_t>(labels[m]) < identities.size()) {
            out[m] = identities[static_cast<std::size_t>(labels[m])];
        }
    }
    return out;
}

}  // namespace ensil::prep

#include "preprocessing/clustering.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "data/error.h"

namespace ensil::prep {
namespace {

constexpr std::array<std::pair<Linkage, const char*>, 4> kLinkageNames{{
    {Linkage::Average, "average"},
    {Linkage::Single, "single"},
    {Linkage::Complete, "complete"},
    {Linkage::Ward, "ward"},
}};

[[noreturn]] void invalid(const std::string& message) {
    throw data::Error(data::ErrorKind::InvalidArgument, message);
}

void validateDistances(const DistanceMatrix& d) {
    if (d.size == 0) invalid("cannot cluster an empty distance matrix (no members)");
    if (d.values.size() != d.size * d.size) {
        invalid("the distance matrix has " + std::to_string(d.values.size()) +
                " entries; a matrix for " + std::to_string(d.size) + " members needs " +
                std::to_string(d.size * d.size));
    }
    for (std::size_t i = 0; i < d.size; ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            const double v = d.at(i, j);
            if (std::isnan(v) || v < 0.0) {
                invalid("distance (" + std::to_string(i) + ", " + std::to_string(j) + ") is " +
                        std::to_string(v) + "; distances must be 0 or more");
            }
            if (v != d.at(j, i)) {
                invalid("the distance matrix is not symmetric at (" + std::to_string(i) + ", " +
                        std::to_string(j) + ")");
            }
        }
    }
}

void validateTree(const MergeTree& tree) {
    const int n = tree.memberCount;
    if (n < 1 || tree.merges.size() != static_cast<std::size_t>(n - 1)) {
        invalid("a merge tree of " + std::to_string(n) + " members needs " +
                std::to_string(std::max(0, n - 1)) + " merges, not " +
                std::to_string(tree.merges.size()));
    }
    for (std::size_t k = 0; k < tree.merges.size(); ++k) {
        const Merge& m = tree.merges[k];
        if (m.a < 0 || m.a >= m.b || m.b >= n + static_cast<int>(k)) {
            invalid("merge " + std::to_string(k) + " joins clusters " + std::to_string(m.a) +
                    " and " + std::to_string(m.b) + ", which do not exist before it");
        }
    }
}

void validateClusterCount(const MergeTree& tree, int k) {
    validateTree(tree);
    if (k < 1 || k > tree.memberCount) {
        invalid("cannot cut " + std::to_string(tree.memberCount) + " members into " +
                std::to_string(k) + " clusters; choose 1 to " + std::to_string(tree.memberCount));
    }
}

// The clusters alive during agglomeration, each in a slot of an N x N distance table (slots of
// merged clusters are reused, so the table never grows).
class Agglomeration {
public:
    Agglomeration(const DistanceMatrix& d, Linkage linkage)
        : m_n(d.size), m_linkage(linkage), m_d(d.values), m_id(d.size), m_size(d.size, 1) {
        for (std::size_t i = 0; i < m_n; ++i) {
            m_id[i] = static_cast<int>(i);
            m_alive.push_back(i);
        }
    }

    // Merges the closest pair of clusters into a new cluster with id N + step.
    Merge mergeClosest(int step) {
        const auto [p, q] = closestPair();
        const double height = m_d[p * m_n + q];
        const int sizeP = m_size[p], sizeQ = m_size[q];
        for (const std::size_t u : m_alive) {
            if (u == p || u == q) continue;
            const double d =
                updated(m_d[u * m_n + p], m_d[u * m_n + q], height, m_size[u], sizeP, sizeQ);
            m_d[u * m_n + p] = d;
            m_d[p * m_n + u] = d;
        }
        const Merge merge{std::min(m_id[p], m_id[q]), std::max(m_id[p], m_id[q]), height,
                          sizeP + sizeQ};
        m_id[p] = static_cast<int>(m_n) + step;  // the new cluster takes slot p
        m_size[p] = sizeP + sizeQ;
        m_alive.erase(std::find(m_alive.begin(), m_alive.end(), q));
        return merge;
    }

private:
    // The slots of the two closest clusters; ties go to the smallest (min id, max id).
    [[nodiscard]] std::pair<std::size_t, std::size_t> closestPair() const {
        std::pair<std::size_t, std::size_t> best{m_alive[0], m_alive[1]};
        double bestD = std::numeric_limits<double>::infinity();
        std::pair<int, int> bestKey{std::numeric_limits<int>::max(), 0};
        for (std::size_t x = 0; x < m_alive.size(); ++x) {
            const std::size_t p = m_alive[x];
            for (std::size_t y = x + 1; y < m_alive.size(); ++y) {
                const std::size_t q = m_alive[y];
                const double d = m_d[p * m_n + q];
                if (d > bestD) continue;
                const std::pair<int, int> key{std::min(m_id[p], m_id[q]),
                                              std::max(m_id[p], m_id[q])};
                if (d < bestD || key < bestKey) {
                    best = {p, q};
                    bestD = d;
                    bestKey = key;
                }
            }
        }
        return best;
    }

    // Lance-Williams update: the distance from cluster u to the union of s and t, given
    // d(u, s), d(u, t) and d(s, t), with SciPy's formulas.
    [[nodiscard]] double updated(double us, double ut, double st, int sizeU, int sizeS,
                                 int sizeT) const {
        switch (m_linkage) {
            case Linkage::Single:
                return std::min(us, ut);
            case Linkage::Complete:
                return std::max(us, ut);
            case Linkage::Average:
                return (sizeS * us + sizeT * ut) / (sizeS + sizeT);
            case Linkage::Ward: {
                const double value = std::sqrt(
                    ((sizeU + sizeS) * us * us + (sizeU + sizeT) * ut * ut - sizeU * st * st) /
                    (sizeU + sizeS + sizeT));
                // Only when everything left is infinitely far apart (inf - inf).
                return std::isnan(value) ? std::numeric_limits<double>::infinity() : value;
            }
        }
        return us;
    }

    std::size_t m_n;
    Linkage m_linkage;
    std::vector<double> m_d;           // m_n x m_n, row-major, by slot
    std::vector<int> m_id;             // cluster id in each slot
    std::vector<int> m_size;           // members in each slot's cluster
    std::vector<std::size_t> m_alive;  // slots holding a cluster, in increasing order
};

// Index of the nearest member of `candidates` to `from` not yet used; ties pick the first.
std::size_t nearestUnused(const DistanceMatrix& d, int from, const std::vector<int>& candidates,
                          const std::vector<bool>& used) {
    std::size_t best = candidates.size();
    double bestDistance = 0.0;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
        if (used[c]) continue;
        const double distance =
            d.at(static_cast<std::size_t>(from), static_cast<std::size_t>(candidates[c]));
        if (best == candidates.size() || distance < bestDistance) {
            best = c;
            bestDistance = distance;
        }
    }
    return best;
}

// The members of one cluster (in increasing index) as a chain from the medoid.
std::vector<int> nearestNeighbourChain(const DistanceMatrix& d, const std::vector<int>& members) {
    std::size_t medoid = 0;
    double medoidSum = std::numeric_limits<double>::infinity();
    for (std::size_t x = 0; x < members.size(); ++x) {
        double sum = 0.0;
        for (const int other : members) {
            sum += d.at(static_cast<std::size_t>(members[x]), static_cast<std::size_t>(other));
        }
        if (x == 0 || sum < medoidSum) {
            medoid = x;
            medoidSum = sum;
        }
    }
    std::vector<bool> used(members.size(), false);
    std::vector<int> chain{members[medoid]};
    used[medoid] = true;
    while (chain.size() < members.size()) {
        const std::size_t next = nearestUnused(d, chain.back(), members, used);
        used[next] = true;
        chain.push_back(members[next]);
    }
    return chain;
}

}  // namespace

Linkage parseLinkage(const std::string& name) {
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const auto& [linkage, text] : kLinkageNames) {
        if (lower == text) return linkage;
    }
    std::vector<std::string> choices;
    choices.reserve(kLinkageNames.size());
    for (const auto& entry : kLinkageNames) choices.emplace_back(entry.second);
    throw data::Error(data::ErrorKind::InvalidArgument,
                      "unknown linkage '" + name + "'; use average, single, complete or ward",
                      std::move(choices));
}

std::string linkageName(Linkage linkage) {
    for (const auto& [value, text] : kLinkageNames) {
        if (value == linkage) return text;
    }
    return "average";
}

MergeTree clusterMembers(const DistanceMatrix& distances, Linkage linkage,
                         const std::stop_token& stop, const data::Progress& progress) {
    validateDistances(distances);
    MergeTree tree;
    tree.memberCount = static_cast<int>(distances.size);
    const int steps = tree.memberCount - 1;
    tree.merges.reserve(static_cast<std::size_t>(steps));
    Agglomeration agglomeration(distances, linkage);
    for (int step = 0; step < steps; ++step) {
        data::throwIfStopped(stop);
        tree.merges.push_back(agglomeration.mergeClosest(step));
        data::report(progress, static_cast<double>(step + 1) / static_cast<double>(steps));
    }
    data::report(progress, 1.0);
    return tree;
}

std::vector<int> leafOrder(const MergeTree& tree) {
    validateTree(tree);
    const int n = tree.memberCount;
    std::vector<int> order;
    order.reserve(static_cast<std::size_t>(n));
    std::vector<int> stack{2 * n - 2};  // the root: the last merge, or member 0 when N = 1
    while (!stack.empty()) {
        const int cluster = stack.back();
        stack.pop_back();
        if (cluster < n) {
            order.push_back(cluster);
        } else {
            const Merge& m = tree.merges[static_cast<std::size_t>(cluster - n)];
            stack.push_back(m.b);  // pushed first, so visited after a
            stack.push_back(m.a);
        }
    }
    return order;
}

std::vector<int> clusterLabels(const MergeTree& tree, int k) {
    validateClusterCount(tree, k);
    const int n = tree.memberCount;
    const int firstUndone = n + (n - k);  // clusters with this id or higher are undone
    const auto total = static_cast<std::size_t>(2 * n - 1);
    std::vector<int> parent(total, -1);
    for (std::size_t r = 0; r < tree.merges.size(); ++r) {
        parent[static_cast<std::size_t>(tree.merges[r].a)] = n + static_cast<int>(r);
        parent[static_cast<std::size_t>(tree.merges[r].b)] = n + static_cast<int>(r);
    }
    // Each cluster's ancestor among the k clusters of the cut. A parent's id is always larger
    // than its children's, so going down the ids visits every parent before its children.
    std::vector<int> top(total, -1);
    for (int c = firstUndone - 1; c >= 0; --c) {
        const int p = parent[static_cast<std::size_t>(c)];
        top[static_cast<std::size_t>(c)] =
            (p < 0 || p >= firstUndone) ? c : top[static_cast<std::size_t>(p)];
    }
    std::vector<int> labelOfTop(total, -1);
    std::vector<int> labels(static_cast<std::size_t>(n), -1);
    int next = 0;
    for (const int leaf : leafOrder(tree)) {
        int& label = labelOfTop[static_cast<std::size_t>(top[static_cast<std::size_t>(leaf)])];
        if (label < 0) label = next++;
        labels[static_cast<std::size_t>(leaf)] = label;
    }
    return labels;
}

double mergeHeightForClusters(const MergeTree& tree, int k) {
    validateClusterCount(tree, k);
    const int n = tree.memberCount;
    if (n == 1) return 0.0;
    if (k == 1) return tree.merges.back().height;
    const double upper = tree.merges[static_cast<std::size_t>(n - k)].height;
    const double lower = k == n ? 0.0 : tree.merges[static_cast<std::size_t>(n - k - 1)].height;
    return 0.5 * (lower + upper);
}

std::vector<int> animationOrder(const MergeTree& tree, const DistanceMatrix& distances, int k) {
    const std::vector<int> labels = clusterLabels(tree, k);
    if (distances.size != labels.size() ||
        distances.values.size() != labels.size() * labels.size()) {
        invalid("the distance matrix is for " + std::to_string(distances.size) +
                " members but the merge tree for " + std::to_string(labels.size()));
    }
    std::vector<std::vector<int>> clusters(static_cast<std::size_t>(k));
    for (std::size_t m = 0; m < labels.size(); ++m) {
        clusters[static_cast<std::size_t>(labels[m])].push_back(static_cast<int>(m));
    }
    std::vector<int> order;
    order.reserve(labels.size());
    for (const auto& members : clusters) {
        const std::vector<int> chain = nearestNeighbourChain(distances, members);
        order.insert(order.end(), chain.begin(), chain.end());
    }
    return order;
}

}  // namespace ensil::prep

#include "widgets/dendrogram_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "widgets/segment_distance.h"

namespace ensil::ui {
namespace {
// Headroom above the root, and how far above the highest finite merge infinite ones are drawn,
// as fractions of that height.
constexpr double kHeadroom = 0.08;
constexpr double kInfiniteLift = 0.15;
}  // namespace

DendrogramLayout::DendrogramLayout(const prep::MergeTree& tree)
    : m_members(tree.memberCount), m_order(prep::leafOrder(tree)) {
    const int n = m_members;
    if (n == 0) return;
    m_nodes.resize(static_cast<std::size_t>(2 * n - 1));
    for (int p = 0; p < n; ++p) {
        Node& leaf = m_nodes[static_cast<std::size_t>(m_order[static_cast<std::size_t>(p)])];
        leaf.x = p + 0.5;
        leaf.first = p;
        leaf.last = p + 1;
    }
    double highestFinite = 0.0;
    for (const prep::Merge& m : tree.merges) {
        if (std::isfinite(m.height)) highestFinite = std::max(highestFinite, m.height);
    }
    if (highestFinite <= 0.0) highestFinite = 1.0;  // all merges at 0 or infinite
    const double infiniteHeight = highestFinite * (1.0 + kInfiniteLift);
    // Children are created before their parent, so one pass in merge order suffices.
    for (std::size_t k = 0; k < tree.merges.size(); ++k) {
        const prep::Merge& m = tree.merges[k];
        Node& node = m_nodes[static_cast<std::size_t>(n) + k];
        Node& a = m_nodes[static_cast<std::size_t>(m.a)];
        Node& b = m_nodes[static_cast<std::size_t>(m.b)];
        node.a = m.a;
        node.b = m.b;
        node.mergeHeight = m.height;
        node.height = std::isfinite(m.height) ? m.height : infiniteHeight;
        node.x = 0.5 * (a.x + b.x);
        node.first = std::min(a.first, b.first);
        node.last = std::max(a.last, b.last);
        a.parent = b.parent = n + static_cast<int>(k);
    }
    m_top = std::max(m_nodes.back().height, highestFinite) * (1.0 + kHeadroom);
    std::vector<double> heights;
    for (int node = n; node < nodeCount(); ++node) heights.push_back(at(node).height);
    if (heights.size() >= 2) {
        std::partial_sort(heights.begin(), heights.begin() + 2, heights.end(), std::greater<>());
        if (heights[1] > 0.0 && heights[0] > kBreakAbove * heights[1]) {
            m_break = heights[1] * (1.0 + kHeadroom);
        }
    }
}

double DendrogramLayout::mergeHeight(int node) const { return at(node).mergeHeight; }
int DendrogramLayout::childA(int node) const { return at(node).a; }
int DendrogramLayout::childB(int node) const { return at(node).b; }

QList<int> DendrogramLayout::membersOf(int node) const {
    const Node& n = at(node);
    QList<int> members;
    members.reserve(n.last - n.first);
    for (int p = n.first; p < n.last; ++p) members << m_order[static_cast<std::size_t>(p)];
    return members;
}

double DendrogramLayout::cutHeight(int k) const {
    const int n = m_members;
    if (n <= 1) return 0.5 * m_top;
    k = std::clamp(k, 1, n);
    if (k == 1) return 0.5 * (m_nodes.back().height + m_top);
    // Merge j is node N + j: the first merge undone is N - k, the last kept N - k - 1.
    const double upper = at(2 * n - k).height;
    const double lower = k == n ? 0.0 : at(2 * n - k - 1).height;
    return 0.5 * (lower + upper);
}

int DendrogramLayout::clustersAtHeight(double height) const {
    const int n = m_members;
    if (n == 0) return 0;
    int kept = 0;  // merges below the line
    for (int node = n; node < nodeCount(); ++node) {
        if (at(node).height < height) ++kept;
    }
    return std::clamp(n - kept, 1, n);
}

bool DendrogramLayout::isBelowCut(int node, int k) const {
    return node < m_members || node - m_members < m_members - k;
}

int nodeAt(const DendrogramLayout& layout, const DendrogramFrame& frame, QPointF p,
           double tolerance) {
    int best = -1;
    double bestDistance = tolerance;
    for (int node = 0; node < layout.nodeCount(); ++node) {
        const QPointF base = frame.toPixel(layout.x(node), layout.height(node));
        double d = std::numeric_limits<double>::infinity();
        if (layout.parent(node) >= 0) {
            const QPointF top = frame.toPixel(layout.x(node), layout.height(layout.parent(node)));
            d = distanceToSegment(p, base, top);
        }
        if (layout.childA(node) >= 0) {
            const QPointF a = frame.toPixel(layout.x(layout.childA(node)), layout.height(node));
            const QPointF b = frame.toPixel(layout.x(layout.childB(node)), layout.height(node));
            d = std::min(d, distanceToSegment(p, a, b));
        }
        if (d <= bestDistance) {
            bestDistance = d;
            best = node;
        }
    }
    return best;
}

}  // namespace ensil::ui

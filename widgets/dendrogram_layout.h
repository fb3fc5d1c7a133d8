// The geometry of a dendrogram, free of painting so it can be tested: where each node (member
// or merge) of a prep::MergeTree sits, which members hang below it, where the cut line for k
// clusters runs, and which node lies under a point. Members sit along x in leaf order, one
// leaf unit apart; merges sit at their height. Merges at infinite height (members with no
// valid point in common) are drawn a little above the highest finite one.
// DendrogramFrame maps these coordinates to pixels (zoom and scroll along x). Value types; any
// thread.
#pragma once

#include <QList>
#include <QPointF>
#include <QRectF>
#include <vector>

#include "preprocessing/clustering.h"

namespace ensil::ui {

class DendrogramLayout {
public:
    DendrogramLayout() = default;
    // Throws data::Error(InvalidArgument) for a malformed tree (as prep::leafOrder).
    explicit DendrogramLayout(const prep::MergeTree& tree);

    [[nodiscard]] int memberCount() const { return m_members; }
    // Members and merges: ids 0..N-1 are members, N + k is merge k, 2N - 2 the root.
    [[nodiscard]] int nodeCount() const { return static_cast<int>(m_nodes.size()); }
    [[nodiscard]] int root() const { return nodeCount() - 1; }
    [[nodiscard]] const std::vector<int>& leafOrder() const { return m_order; }
    // Leaf units: the p-th leaf of the leaf order at p + 0.5; a merge midway between its
    // children.
    [[nodiscard]] double x(int node) const { return at(node).x; }
    // The height a node is drawn at (0 for members, finite for every merge).
    [[nodiscard]] double height(int node) const { return at(node).height; }
    // The merge height as computed (may be +infinity).
    [[nodiscard]] double mergeHeight(int node) const;
    [[nodiscard]] int parent(int node) const { return at(node).parent; }  // -1 for the root
    [[nodiscard]] int childA(int node) const;                             // -1 for members
    [[nodiscard]] int childB(int node) const;
    // The members below a node, in leaf order.
    [[nodiscard]] QList<int> membersOf(int node) const;
    [[nodiscard]] int memberCountOf(int node) const { return at(node).last - at(node).first; }
    // The first member below a node in leaf order.
    [[nodiscard]] int firstMember(int node) const {
        return m_order[static_cast<std::size_t>(at(node).first)];
    }
    // The drawn height of the root plus headroom: the top of the plot.
    [[nodiscard]] double topHeight() const { return m_top; }
    // Where the height axis is broken (0: it is not): when the highest merge stands more than
    // kBreakAbove times above the next (one far outlier joining last), a linear axis squeezes
    // every other merge into the plot's bottom pixels, with the cut lines among them; the axis
    // then runs linearly up to just above the second-highest merge over most of the plot, and
    // the rest above a break (DendrogramFrame).
    [[nodiscard]] double breakHeight() const { return m_break; }
    static constexpr double kBreakAbove = 4.0;

    // Where the cut line for k clusters is drawn: midway between the last merge kept and the
    // first undone; for k = 1 between the root and the top. k is clamped to 1..N.
    [[nodiscard]] double cutHeight(int k) const;
    // The number of clusters a cut line at this drawn height makes (1..N).
    [[nodiscard]] int clustersAtHeight(double height) const;
    // Whether a node lies below the cut for k clusters (its members share one cluster).
    [[nodiscard]] bool isBelowCut(int node, int k) const;

private:
    struct Node {
        double x = 0.0;
        double height = 0.0;
        double mergeHeight = 0.0;
        int first = 0;  // members below: leafOrder()[first, last)
        int last = 0;
        int parent = -1;
        int a = -1;
        int b = -1;
    };
    [[nodiscard]] const Node& at(int node) const {
        return m_nodes.at(static_cast<std::size_t>(node));
    }

    int m_members = 0;
    std::vector<int> m_order;
    std::vector<Node> m_nodes;
    double m_top = 1.0;
    double m_break = 0.0;
};

// Maps dendrogram coordinates to pixels: x in leaf units times leafWidth, minus the scroll;
// heights from 0 at the plot's bottom to topHeight at its top.
struct DendrogramFrame {
    QRectF plot;              // pixels the tree is drawn in (labels go below it)
    double leafWidth = 10.0;  // pixels per leaf
    double scroll = 0.0;      // pixels scrolled to the right
    double topHeight = 1.0;
    // Heights above this one are drawn above a break in the axis, in its top kAboveBreak of the
    // plot (DendrogramLayout::breakHeight; 0: one linear axis), as the axis shows.
    double breakHeight = 0.0;
    static constexpr double kAboveBreak = 0.2;

    [[nodiscard]] double pixelX(double leafX) const {
        return plot.left() + leafX * leafWidth - scroll;
    }
    // The fraction of the plot's height a height is drawn at, and back.
    [[nodiscard]] double fractionOf(double height) const {
        if (breakHeight <= 0.0 || breakHeight >= topHeight) return height / topHeight;
        if (height <= breakHeight) return (1.0 - kAboveBreak) * height / breakHeight;
        return 1.0 - kAboveBreak + kAboveBreak * (height - breakHeight) / (topHeight - breakHeight);
    }
    [[nodiscard]] double heightOf(double fraction) const {
        if (breakHeight <= 0.0 || breakHeight >= topHeight) return fraction * topHeight;
        if (fraction <= 1.0 - kAboveBreak) return fraction / (1.0 - kAboveBreak) * breakHeight;
        return breakHeight +
               (fraction - (1.0 - kAboveBreak)) / kAboveBreak * (topHeight - breakHeight);
    }
    [[nodiscard]] double pixelY(double height) const {
        return plot.bottom() - fractionOf(height) * plot.height();
    }
    [[nodiscard]] QPointF toPixel(double leafX, double height) const {
        return {pixelX(leafX), pixelY(height)};
    }
    [[nodiscard]] double heightAt(double y) const {
        return heightOf((plot.bottom() - y) / plot.height());
    }
};

// The node whose line is nearest to point p, within `tolerance` pixels; -1 for none. A
// member's and a merge's line is its vertical stem up to its parent; a merge also owns the
// horizontal bar joining its children.
int nodeAt(const DendrogramLayout& layout, const DendrogramFrame& frame, QPointF p,
           double tolerance = 4.0);

}  // namespace ensil::ui

// The dendrogram dock: the merge tree of the shared workbench::MemberSelection, painted by
// paintDendrogram. Drag the dashed cut line up or down to choose the number of clusters (live);
// click a branch to select its members (Shift adds, Ctrl toggles; a click on empty space
// clears); hover a branch for its merge height (its members are shaded), a member's stem to
// hover the member; the contour boxplot's marks and legend say what they mean. The wheel
// zooms along the leaves around the pointer, Shift + wheel (or a sideways wheel) scrolls.
// GUI thread only.
#pragma once

#include <QAbstractScrollArea>

#include "widgets/dendrogram_layout.h"
#include "widgets/dendrogram_painter.h"

namespace ensil::workbench {
class MemberSelection;
}  // namespace ensil::workbench

namespace ensil::ui {

class DendrogramView : public QAbstractScrollArea {
    Q_OBJECT
public:
    explicit DendrogramView(workbench::MemberSelection* selection, QWidget* parent = nullptr);

    [[nodiscard]] const DendrogramLayout& layout() const { return m_layout; }
    // The pixel frame the tree is drawn in now (viewport coordinates).
    [[nodiscard]] DendrogramFrame frame() const;
    [[nodiscard]] double zoom() const { return m_zoom; }
    void setZoom(double zoom, double anchorX);  // keeps the leaf under anchorX in place
    [[nodiscard]] DendrogramStyle style() const;
    // The branch (node) under the pointer, shaded; -1 for none.
    [[nodiscard]] int hoveredNode() const { return m_hoveredNode; }
    // The text the tooltip shows at a viewport point (empty when nothing is there).
    [[nodiscard]] QString toolTipAt(QPointF p) const;

    [[nodiscard]] QSize sizeHint() const override { return {600, 260}; }
    [[nodiscard]] QSize minimumSizeHint() const override { return {200, 120}; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    bool viewportEvent(QEvent* event) override;

private:
    void rebuildLayout();
    void updateScrollBar();
    [[nodiscard]] double leafWidth() const;
    [[nodiscard]] double fitLeafWidth() const;
    [[nodiscard]] bool isOnCutLine(QPointF p) const;
    void dragCutTo(double y);
    void setHoveredNode(int node);
    // "inclusion depth 0.672, the median of the contour boxplot ..."; empty when not known.
    [[nodiscard]] QString boxplotText(int member) const;

    workbench::MemberSelection* m_selection;
    DendrogramLayout m_layout;
    double m_zoom = 1.0;  // 1: all leaves fit the width
    bool m_draggingCut = false;
    int m_hoveredNode = -1;
};

}  // namespace ensil::ui

#include "widgets/dendrogram_view.h"

#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>
#include <QToolTip>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "workbench/member_selection.h"

namespace ensil::ui {
namespace {
constexpr double kCutGrab = 5.0;  // pixels either side of the cut line that grab it
constexpr double kMaxLeafWidth = 60.0;
constexpr double kZoomStep = 1.25;  // per wheel notch
constexpr double kMarkGrab = 6.0;   // pixels above and below the boxplot marks that tell them
}  // namespace

DendrogramView::DendrogramView(workbench::MemberSelection* selection, QWidget* parent)
    : QAbstractScrollArea(parent), m_selection(selection) {
    setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    viewport()->setMouseTracking(true);
    viewport()->setBackgroundRole(QPalette::Base);
    horizontalScrollBar()->setSingleStep(20);
    connect(horizontalScrollBar(), &QScrollBar::valueChanged, viewport(),
            qOverload<>(&QWidget::update));
    connect(selection, &workbench::MemberSelection::clustersChanged, this,
            &DendrogramView::rebuildLayout);
    connect(selection, &workbench::MemberSelection::membersReset, this,
            &DendrogramView::rebuildLayout);
    connect(selection, &workbench::MemberSelection::selectionChanged, viewport(),
            qOverload<>(&QWidget::update));
    connect(selection, &workbench::MemberSelection::hoverChanged, viewport(),
            qOverload<>(&QWidget::update));
    rebuildLayout();
}

void DendrogramView::rebuildLayout() {
    // The tree changes with the isovalue or the linkage; a new cut keeps the tree but the
    // layout is cheap (linear in the members) so it is simply rebuilt.
    m_layout =
        m_selection->isClustered() ? DendrogramLayout(m_selection->tree()) : DendrogramLayout();
    // Node ids stay valid across a new cut, not across a new tree or new members.
    if (m_hoveredNode >= m_layout.nodeCount()) m_hoveredNode = -1;
    updateScrollBar();
    viewport()->update();
}

DendrogramStyle DendrogramView::style() const {
    DendrogramStyle s;
    s.background = palette().color(QPalette::Base);
    s.text = palette().color(QPalette::Text);
    s.line = palette().color(QPalette::PlaceholderText);
    s.selection = palette().color(QPalette::Text);
    s.hover = palette().color(QPalette::Highlight);
    s.hover.setAlpha(50);
    s.median = palette().color(QPalette::Text);
    s.font = font();
    return s;
}

double DendrogramView::fitLeafWidth() const {
    const int n = std::max(1, m_layout.memberCount());
    const DendrogramMargins margins = dendrogramMargins(*m_selection, font(), 0.0);
    const double width = viewport()->width() - margins.left - margins.right;
    return std::max(1.0, width / n);
}

double DendrogramView::leafWidth() const {
    return std::min(fitLeafWidth() * m_zoom, std::max(fitLeafWidth(), kMaxLeafWidth));
}

DendrogramFrame DendrogramView::frame() const {
    return dendrogramFrame(m_layout, *m_selection, QRectF(viewport()->rect()), font(), leafWidth(),
                           horizontalScrollBar()->value());
}

void DendrogramView::updateScrollBar() {
    const DendrogramFrame f = frame();
    const double content = leafWidth() * m_layout.memberCount();
    const int excess = static_cast<int>(std::ceil(content - f.plot.width()));
    horizontalScrollBar()->setRange(0, std::max(0, excess));
    horizontalScrollBar()->setPageStep(static_cast<int>(f.plot.width()));
}

void DendrogramView::setZoom(double zoom, double anchorX) {
    const DendrogramFrame before = frame();
    const double leafUnderAnchor =
        (anchorX - before.plot.left() + before.scroll) / before.leafWidth;
    m_zoom = std::clamp(zoom, 1.0, std::max(1.0, kMaxLeafWidth / fitLeafWidth()));
    updateScrollBar();
    const DendrogramFrame after = frame();
    horizontalScrollBar()->setValue(static_cast<int>(
        std::lround(leafUnderAnchor * after.leafWidth - (anchorX - after.plot.left()))));
    viewport()->update();
}

QString DendrogramView::boxplotText(int member) const {
    const double depth = m_selection->depth(member);
    if (std::isnan(depth)) return {};
    const QString value = workbench::depthText(depth);
    if (m_selection->isMedian(member)) {
        return tr("inclusion depth %1, the median of the contour boxplot (the deepest member)")
            .arg(value);
    }
    if (m_selection->isOutlier(member)) {
        return tr("inclusion depth %1, an outlier of the contour boxplot (below the lower fence)")
            .arg(value);
    }
    return tr("inclusion depth %1").arg(value);
}

QString DendrogramView::toolTipAt(QPointF p) const {
    const DendrogramFrame f = frame();
    if (m_selection->clusterCount() > 0 && isOnCutLine(p)) {
        return tr("Cut into %1 clusters: drag up or down to change")
            .arg(m_selection->clusterCount());
    }
    const QRectF viewArea(viewport()->rect());
    if (boxplotLegendRect(*m_selection, viewArea, f, font()).contains(p)) {
        return tr(
            "Contour boxplot of the members' isosurfaces at this isovalue: a diamond marks "
            "the median (the deepest, most central member, its name in bold), a triangle "
            "each outlier (inclusion depth below Q1 - 1.5 IQR, its name in italics)");
    }
    // The row of boxplot marks under the leaves: the member whose mark is there.
    if (m_selection->hasBoxplot() && m_layout.memberCount() > 0) {
        const QPointF mark = boxplotMarkCenter(f, 0.5);
        const double leaf = std::floor((p.x() - f.plot.left() + f.scroll) / f.leafWidth);
        if (std::abs(p.y() - mark.y()) <= kMarkGrab && leaf >= 0 && leaf < m_layout.memberCount() &&
            p.x() >= f.plot.left() && p.x() <= f.plot.right()) {
            const int member = m_layout.leafOrder()[static_cast<std::size_t>(leaf)];
            return tr("%1: %2").arg(m_selection->name(member), boxplotText(member));
        }
    }
    const int node = nodeAt(m_layout, f, p);
    if (node < 0) return {};
    if (node < m_layout.memberCount()) {
        const QString text = tr("%1 (cluster %2)")
                                 .arg(m_selection->name(node))
                                 .arg(m_selection->clusterNumber(m_selection->clusterOf(node)));
        const QString boxplot = boxplotText(node);
        return boxplot.isEmpty() ? text : tr("%1, %2").arg(text, boxplot);
    }
    const double h = m_layout.mergeHeight(node);
    return tr("Merge height %1: %2 members")
        .arg(std::isfinite(h) ? QString::number(h, 'g', 4) : tr("infinite (no common points)"))
        .arg(m_layout.memberCountOf(node));
}

bool DendrogramView::isOnCutLine(QPointF p) const {
    const int k = m_selection->clusterCount();
    if (k == 0) return false;
    const DendrogramFrame f = frame();
    return std::abs(p.y() - f.pixelY(m_layout.cutHeight(k))) <= kCutGrab &&
           p.x() >= f.plot.left() && p.x() <= f.plot.right();
}

void DendrogramView::dragCutTo(double y) {
    const int k = m_layout.clustersAtHeight(frame().heightAt(y));
    if (k > 0) m_selection->setClusterCount(k);
}

void DendrogramView::paintEvent(QPaintEvent* /*event*/) {
    QPainter painter(viewport());
    paintDendrogram(painter, QRectF(viewport()->rect()), m_layout, *m_selection, frame(), style(),
                    m_hoveredNode);
}

void DendrogramView::resizeEvent(QResizeEvent* event) {
    QAbstractScrollArea::resizeEvent(event);
    updateScrollBar();
}

void DendrogramView::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return;
    const QPointF p = event->position();
    if (isOnCutLine(p)) {
        m_draggingCut = true;
        return;
    }
    const int node = nodeAt(m_layout, frame(), p);
    m_selection->click(node < 0 ? QList<int>{} : m_layout.membersOf(node), event->modifiers());
}

void DendrogramView::mouseMoveEvent(QMouseEvent* event) {
    const QPointF p = event->position();
    if (m_draggingCut) {
        dragCutTo(p.y());
        return;
    }
    viewport()->setCursor(isOnCutLine(p) ? Qt::SplitVCursor : Qt::ArrowCursor);
    const int node = nodeAt(m_layout, frame(), p);
    setHoveredNode(node);
    m_selection->setHovered(node >= 0 && node < m_layout.memberCount() ? node : -1);
}

void DendrogramView::setHoveredNode(int node) {
    if (node == m_hoveredNode) return;
    m_hoveredNode = node;
    viewport()->update();
}

void DendrogramView::mouseReleaseEvent(QMouseEvent* event) {
    if (m_draggingCut) dragCutTo(event->position().y());
    m_draggingCut = false;
}

void DendrogramView::wheelEvent(QWheelEvent* event) {
    const QPoint delta = event->angleDelta();
    if (event->modifiers().testFlag(Qt::ShiftModifier) || delta.x() != 0) {
        const int steps = (delta.x() != 0 ? delta.x() : delta.y()) / 8;
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() - steps * 2);
    } else if (delta.y() != 0) {
        setZoom(m_zoom * std::pow(kZoomStep, delta.y() / 120.0), event->position().x());
    }
    event->accept();
}

bool DendrogramView::viewportEvent(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        const QString text = toolTipAt(help->pos());
        if (text.isEmpty()) {
            QToolTip::hideText();
        } else {
            QToolTip::showText(help->globalPos(), text, viewport());
        }
        return true;
    }
    if (event->type() == QEvent::Leave) {
        setHoveredNode(-1);
        m_selection->setHovered(-1);
    }
    return QAbstractScrollArea::viewportEvent(event);
}

}  // namespace ensil::ui

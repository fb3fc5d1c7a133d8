#include "widgets/dendrogram_painter.h"

#include <QFontMetricsF>
#include <QObject>
#include <QPainterPath>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "gl/axis_ticks.h"
#include "workbench/member_selection.h"

namespace ensil::ui {
namespace {
constexpr double kTickLength = 4.0;
constexpr int kTicks = 4;
// Selection markers hang below the leaves (radius up to 5 px); names start below them.
constexpr double kNamesOffset = 14.0;
constexpr double kNamesStart = 8.0;
constexpr double kMaxNameWidth = 140.0;  // longer names are elided
// The contour boxplot's marks (radius up to 4.5 px) hang below the selection markers, in a row
// of their own that moves the names down when there is a boxplot.
constexpr double kMarksTop = 12.0;
constexpr double kMaxMarkRadius = 4.5;
constexpr double kMarksRow = 14.0;
constexpr double kLegendMarkGap = 3.0;  // between a legend entry's mark and its text

double marksRow(const workbench::MemberSelection& selection) {
    return selection.hasBoxplot() ? kMarksRow : 0.0;
}

// A filled diamond (the median) or triangle pointing up (an outlier) of this radius.
void drawMark(QPainter& painter, QPointF at, double r, bool median, const DendrogramStyle& style) {
    painter.setPen(Qt::NoPen);
    painter.setBrush(median ? style.median : style.outlier);
    if (median) {
        const std::array<QPointF, 4> diamond{at + QPointF(0, -r), at + QPointF(r, 0),
                                             at + QPointF(0, r), at + QPointF(-r, 0)};
        painter.drawPolygon(diamond.data(), static_cast<int>(diamond.size()));
    } else {
        const std::array<QPointF, 3> triangle{at + QPointF(0, -r), at + QPointF(r, 0.8 * r),
                                              at + QPointF(-r, 0.8 * r)};
        painter.drawPolygon(triangle.data(), static_cast<int>(triangle.size()));
    }
    painter.setBrush(Qt::NoBrush);
}

// The legend's entries: mark (median or not) and text.
struct LegendEntry {
    bool median;
    QString text;
};
std::array<LegendEntry, 2> legendEntries() {
    return {LegendEntry{true, QObject::tr("median")}, LegendEntry{false, QObject::tr("outlier")}};
}
double legendMarkRadius(const QFontMetricsF& metrics) { return 0.3 * metrics.ascent(); }
// The first entry's baseline below the plot: its mark level with the marks under the leaves.
double legendBaseline(const QFontMetricsF& metrics) {
    return kMarksTop + kMaxMarkRadius + metrics.ascent() / 2.0 - 1.0;
}
// How far below the plot the legend reaches: two lines from legendBaseline.
double legendBottom(const QFontMetricsF& metrics) {
    return legendBaseline(metrics) + metrics.lineSpacing() + metrics.descent();
}

// Names are drawn (turned 90 degrees) only when a line of text fits between two leaves.
bool namesFit(const QFont& font, double leafWidth) {
    return leafWidth >= QFontMetricsF(font).height();
}

double longestName(const workbench::MemberSelection& selection, const QFont& font) {
    double widest = 0.0;
    for (int m = 0; m < selection.memberCount(); ++m) {
        const QFontMetricsF metrics(dendrogramLeafFont(selection, m, font));
        widest = std::max(widest, metrics.horizontalAdvance(selection.name(m)));
    }
    return std::min(widest, kMaxNameWidth);  // long names are elided
}

// Every node whose members are all selected.
std::vector<bool> fullySelected(const DendrogramLayout& layout,
                                const workbench::MemberSelection& selection) {
    std::vector<bool> all(static_cast<std::size_t>(layout.nodeCount()), false);
    for (int node = 0; node < layout.nodeCount(); ++node) {
        all[static_cast<std::size_t>(node)] =
            node < layout.memberCount() ? selection.isSelected(node)
                                        : all[static_cast<std::size_t>(layout.childA(node))] &&
                                              all[static_cast<std::size_t>(layout.childB(node))];
    }
    return all;
}

QColor nodeColor(int node, const DendrogramLayout& layout,
                 const workbench::MemberSelection& selection, const DendrogramStyle& style) {
    const int k = selection.clusterCount();
    if (k == 0 || !layout.isBelowCut(node, k)) return style.line;
    return selection.memberColor(layout.firstMember(node));
}

void drawAxis(QPainter& painter, const DendrogramFrame& frame, const DendrogramStyle& style) {
    painter.setPen(QPen(style.text, 1.0));
    const QFontMetricsF metrics(style.font);
    const double x = frame.plot.left();
    painter.drawLine(QPointF(x, frame.plot.top()), QPointF(x, frame.plot.bottom()));
    // Round merge heights (1, 2, 2.5 or 5 times a power of ten), as on the view's axes: below
    // a break, of the heights there, and above it, of the heights beyond.
    std::vector<double> ticks;
    if (frame.breakHeight > 0.0) {
        ticks = gl::niceTicks(0.0, frame.breakHeight, kTicks);
        for (const double h : gl::niceTicks(frame.breakHeight, frame.topHeight, 2)) {
            if (h > frame.breakHeight) ticks.push_back(h);
        }
    } else {
        ticks = gl::niceTicks(0.0, frame.topHeight, kTicks);
    }
    double lastY = std::numeric_limits<double>::infinity();
    for (const double h : ticks) {
        const double y = frame.pixelY(h);
        if (lastY - y < metrics.height()) continue;  // too near the tick below
        lastY = y;
        painter.drawLine(QPointF(x - kTickLength, y), QPointF(x, y));
        const QString label = QString::number(h, 'g', 3);
        const double w = metrics.horizontalAdvance(label);
        painter.drawText(QPointF(x - kTickLength - 2.0 - w, y + metrics.ascent() / 2.0), label);
    }
    // A break: the axis's line is interrupted by two slanted strokes, as on a printed chart.
    if (frame.breakHeight > 0.0) {
        const double y = frame.pixelY(frame.breakHeight);
        painter.save();
        painter.setPen(QPen(style.background, 3.0));
        painter.drawLine(QPointF(x, y - 3.0), QPointF(x, y + 3.0));
        painter.setPen(QPen(style.text, 1.0));
        for (const double dy : {-3.0, 3.0}) {
            painter.drawLine(QPointF(x - 4.0, y + dy + 2.0), QPointF(x + 4.0, y + dy - 2.0));
        }
        painter.restore();
    }
}

void drawNames(QPainter& painter, const DendrogramLayout& layout,
               const workbench::MemberSelection& selection, const DendrogramFrame& frame,
               const DendrogramStyle& style) {
    const QFontMetricsF metrics(style.font);
    painter.setPen(style.text);
    const double top = frame.plot.bottom() + kNamesStart + marksRow(selection);
    for (int p = 0; p < layout.memberCount(); ++p) {
        const int member = layout.leafOrder()[static_cast<std::size_t>(p)];
        const double x = frame.pixelX(p + 0.5);
        if (x < frame.plot.left() - 1.0 || x > frame.plot.right() + 1.0) continue;
        painter.save();
        painter.setFont(dendrogramLeafFont(selection, member, style.font));
        painter.translate(x + metrics.ascent() / 2.0 - metrics.descent(), top);
        painter.rotate(90.0);
        // Elided in the middle: names that differ at their end (dates) stay told apart.
        painter.drawText(QPointF(0.0, 0.0),
                         QFontMetricsF(painter.font())
                             .elidedText(selection.name(member), Qt::ElideMiddle, kMaxNameWidth));
        painter.restore();
    }
}

// The contour boxplot's marks under the leaves of the median and the outliers.
void drawBoxplotMarks(QPainter& painter, const DendrogramLayout& layout,
                      const workbench::MemberSelection& selection, const DendrogramFrame& frame,
                      const DendrogramStyle& style) {
    const double r = boxplotMarkRadius(frame);
    for (int p = 0; p < layout.memberCount(); ++p) {
        const int member = layout.leafOrder()[static_cast<std::size_t>(p)];
        const bool median = selection.isMedian(member);
        if (!median && !selection.isOutlier(member)) continue;
        drawMark(painter, boxplotMarkCenter(frame, p + 0.5), r, median, style);
    }
}

// What the marks mean, in the corner below the height axis, beside the leaves: "<diamond>
// median" level with the marks, "<triangle> outlier" below it.
void drawBoxplotLegend(QPainter& painter, const workbench::MemberSelection& selection,
                       const QRectF& area, const DendrogramFrame& frame,
                       const DendrogramStyle& style) {
    const QRectF rect = boxplotLegendRect(selection, area, frame, style.font);
    if (rect.isEmpty()) return;
    const QFontMetricsF metrics(style.font);
    const double r = legendMarkRadius(metrics);
    double baseline = frame.plot.bottom() + legendBaseline(metrics);
    for (const LegendEntry& entry : legendEntries()) {
        drawMark(painter, QPointF(rect.left() + r, baseline - metrics.ascent() / 2.0 + 1.0), r,
                 entry.median, style);
        painter.setPen(style.text);
        painter.drawText(QPointF(rect.left() + 2.0 * r + kLegendMarkGap, baseline), entry.text);
        baseline += metrics.lineSpacing();
    }
}
}  // namespace

DendrogramMargins dendrogramMargins(const workbench::MemberSelection& selection, const QFont& font,
                                    double leafWidth) {
    const QFontMetricsF metrics(font);
    DendrogramMargins margins;
    margins.left = metrics.horizontalAdvance(QStringLiteral("0.000e-00")) + kTickLength + 6.0;
    margins.top = metrics.height() / 2.0 + 2.0;
    margins.right = 8.0;
    margins.bottom = kNamesOffset + 2.0 + marksRow(selection) +
                     (namesFit(font, leafWidth) ? longestName(selection, font) : 0.0);
    // Room for the boxplot's legend in the corner below the axis, names or not.
    if (selection.hasBoxplot()) {
        margins.bottom = std::max(margins.bottom, legendBottom(metrics) + 2.0);
    }
    return margins;
}

QFont dendrogramLeafFont(const workbench::MemberSelection& selection, int member,
                         const QFont& font) {
    QFont f = font;
    if (selection.isMedian(member)) {
        f.setBold(true);
    } else if (selection.isOutlier(member)) {
        f.setItalic(true);
    }
    return f;
}

QPointF boxplotMarkCenter(const DendrogramFrame& frame, double leafX) {
    return {frame.pixelX(leafX), frame.plot.bottom() + kMarksTop + kMaxMarkRadius};
}

double boxplotMarkRadius(const DendrogramFrame& frame) {
    return std::clamp(frame.leafWidth * 0.35, 2.5, kMaxMarkRadius);
}

QRectF boxplotLegendRect(const workbench::MemberSelection& selection, const QRectF& area,
                         const DendrogramFrame& frame, const QFont& font) {
    if (!selection.hasBoxplot()) return {};
    const QFontMetricsF metrics(font);
    double width = 0.0;
    for (const LegendEntry& entry : legendEntries()) {
        width = std::max(width, 2.0 * legendMarkRadius(metrics) + kLegendMarkGap +
                                    metrics.horizontalAdvance(entry.text));
    }
    const double top = frame.plot.bottom() + legendBaseline(metrics) - metrics.ascent();
    return {area.left() + 2.0, top, width, frame.plot.bottom() + legendBottom(metrics) - top};
}

DendrogramFrame dendrogramFrame(const DendrogramLayout& layout,
                                const workbench::MemberSelection& selection, const QRectF& area,
                                const QFont& font, double leafWidth, double scroll) {
    const DendrogramMargins margins = dendrogramMargins(selection, font, leafWidth);
    DendrogramFrame frame;
    frame.plot = area.adjusted(margins.left, margins.top, -margins.right, -margins.bottom);
    if (frame.plot.height() < 1.0) frame.plot.setHeight(1.0);
    frame.leafWidth = leafWidth;
    frame.scroll = scroll;
    frame.topHeight = layout.topHeight();
    frame.breakHeight = layout.breakHeight();
    return frame;
}

void paintDendrogram(QPainter& painter, const QRectF& area, const DendrogramLayout& layout,
                     const workbench::MemberSelection& selection, const DendrogramFrame& frame,
                     const DendrogramStyle& style, int hoveredNode) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setFont(style.font);
    painter.fillRect(area, style.background);
    if (layout.memberCount() == 0) {
        painter.setPen(style.text);
        painter.drawText(area, Qt::AlignCenter,
                         QObject::tr("No clusters yet: the dendrogram appears when the members "
                                     "of an isovalue have been compared."));
        painter.restore();
        return;
    }
    drawAxis(painter, frame, style);
    // Leaves scrolled out of the plot must not draw over the axis.
    painter.setClipRect(
        QRectF(frame.plot.left() - 2.0, area.top(), frame.plot.width() + 4.0, area.height()));

    if (hoveredNode >= 0 && hoveredNode < layout.nodeCount()) {
        const double first = layout.x(layout.firstMember(hoveredNode)) - 0.5;
        const double top = layout.height(hoveredNode) +
                           (hoveredNode < layout.memberCount() ? 0.02 * layout.topHeight() : 0.0);
        painter.fillRect(QRectF(frame.toPixel(first, top),
                                frame.toPixel(first + layout.memberCountOf(hoveredNode), 0.0)),
                         style.hover);
    }

    const std::vector<bool> selected = fullySelected(layout, selection);
    // Stems first, then bars, each in its node's colour; selected branches thicker.
    for (int node = 0; node < layout.nodeCount(); ++node) {
        const bool thick = selected[static_cast<std::size_t>(node)];
        QPen pen(nodeColor(node, layout, selection, style),
                 thick ? 2.5 * style.lineWidth : style.lineWidth);
        pen.setCapStyle(Qt::FlatCap);
        painter.setPen(pen);
        const double x = layout.x(node);
        if (layout.parent(node) >= 0) {
            painter.drawLine(frame.toPixel(x, layout.height(node)),
                             frame.toPixel(x, layout.height(layout.parent(node))));
        }
        if (layout.childA(node) >= 0) {
            painter.drawLine(frame.toPixel(layout.x(layout.childA(node)), layout.height(node)),
                             frame.toPixel(layout.x(layout.childB(node)), layout.height(node)));
        }
    }

    // Markers under the selected members and the hovered one.
    const double radius = std::clamp(frame.leafWidth * 0.3, 2.0, 5.0);
    for (int p = 0; p < layout.memberCount(); ++p) {
        const int member = layout.leafOrder()[static_cast<std::size_t>(p)];
        const bool hovered = member == selection.hovered();
        if (!selection.isSelected(member) && !hovered) continue;
        const QPointF at(frame.pixelX(p + 0.5), frame.plot.bottom() + radius + 1.0);
        painter.setPen(QPen(style.selection, hovered ? 2.0 : 1.0));
        painter.setBrush(selection.isSelected(member) ? QBrush(selection.memberColor(member))
                                                      : Qt::NoBrush);
        painter.drawEllipse(at, radius, radius);
    }
    painter.setBrush(Qt::NoBrush);
    if (selection.hasBoxplot()) drawBoxplotMarks(painter, layout, selection, frame, style);
    if (namesFit(style.font, frame.leafWidth)) drawNames(painter, layout, selection, frame, style);

    // The cut line across the whole plot, with the number of clusters at its right end.
    const int k = selection.clusterCount();
    if (k > 0) {
        painter.setClipping(false);
        const double y = frame.pixelY(layout.cutHeight(k));
        QPen pen(style.cut, 1.5, Qt::DashLine);
        painter.setPen(pen);
        painter.drawLine(QPointF(frame.plot.left(), y), QPointF(frame.plot.right(), y));
        const QString label = k == 1 ? QObject::tr("1 cluster") : QObject::tr("%1 clusters").arg(k);
        const QFontMetricsF metrics(style.font);
        painter.drawText(QPointF(frame.plot.right() - metrics.horizontalAdvance(label) - 2.0,
                                 y - metrics.descent() - 2.0),
                         label);
    }
    painter.setClipping(false);
    drawBoxplotLegend(painter, selection, area, frame, style);
    painter.restore();
}

}  // namespace ensil::ui

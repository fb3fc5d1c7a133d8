// Paints a dendrogram with QPainter, for the on-screen DendrogramView and for SVG export alike:
// a height axis, the tree (branches below the cut in their cluster's colour, the rest in the
// line colour; branches whose members are all selected drawn thicker), a marker under every
// selected or hovered member, the members' names when there is room, and the cut line. When the
// contour boxplot is known, a row of marks under the leaves (a diamond under the median, the
// deepest member; a triangle under each outlier; drawn at any zoom, names or not), the median's
// name in bold and the outliers' in italics, and a legend saying what the marks are in the
// corner below the height axis. (Words after the names would take the plot's height: the names
// are turned on their side.)
// GUI thread (QPainter on widgets); any thread for QSvgGenerator / QImage targets.
#pragma once

#include <QColor>
#include <QPainter>

#include "widgets/dendrogram_layout.h"

namespace ensil::workbench {
class MemberSelection;
}  // namespace ensil::workbench

namespace ensil::ui {

struct DendrogramStyle {
    QColor background{Qt::white};
    QColor line{90, 90, 90};
    QColor text{Qt::black};
    QColor cut{200, 30, 30};
    QColor selection{20, 20, 20};
    QColor hover{60, 120, 220, 50};  // the band behind the branch under the pointer
    QColor median{20, 20, 20};       // the median's mark (contour boxplot)
    QColor outlier{213, 94, 0};      // the outliers' marks (vermilion)
    QFont font;
    double lineWidth = 1.5;
};

// Pixels the painter reserves around the plot: the height axis on the left, the names below.
struct DendrogramMargins {
    double left = 0.0;
    double bottom = 0.0;
    double top = 0.0;
    double right = 0.0;
};
DendrogramMargins dendrogramMargins(const workbench::MemberSelection& selection, const QFont& font,
                                    double leafWidth);

// The font of the name under a member's leaf: bold for the contour boxplot's median, italic for
// its outliers, else the font given.
QFont dendrogramLeafFont(const workbench::MemberSelection& selection, int member,
                         const QFont& font);

// The contour boxplot's row of marks under the leaves (only drawn when the boxplot is known):
// the centre of the mark under the leaf at leafX (leaf units) and the marks' radius.
QPointF boxplotMarkCenter(const DendrogramFrame& frame, double leafX);
double boxplotMarkRadius(const DendrogramFrame& frame);
// Where the legend of those marks is drawn: in the corner below the height axis, left of the
// leaves, its first entry level with the marks (empty when the boxplot is not known).
QRectF boxplotLegendRect(const workbench::MemberSelection& selection, const QRectF& area,
                         const DendrogramFrame& frame, const QFont& font);

// The frame that fits `members` leaves `leafWidth` pixels apart into `area` after margins.
DendrogramFrame dendrogramFrame(const DendrogramLayout& layout,
                                const workbench::MemberSelection& selection, const QRectF& area,
                                const QFont& font, double leafWidth, double scroll);

// Paints into `area` of the painter's device. A band behind `hoveredNode` (the branch under the
// pointer; -1 for none) shows the members a click there would select.
void paintDendrogram(QPainter& painter, const QRectF& area, const DendrogramLayout& layout,
                     const workbench::MemberSelection& selection, const DendrogramFrame& frame,
                     const DendrogramStyle& style, int hoveredNode = -1);

}  // namespace ensil::ui

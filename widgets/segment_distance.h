// How far a point lies from a line segment, in the units of both (widget pixels): what picking
// a drawn line (a dendrogram's branch, a section's contour) asks. Pure; any thread.
#pragma once

#include <QPointF>
#include <algorithm>
#include <cmath>

namespace ensil::ui {

inline double distanceToSegment(QPointF p, QPointF a, QPointF b) {
    const QPointF d = b - a;
    const double length2 = QPointF::dotProduct(d, d);
    const double t =
        length2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, d) / length2, 0.0, 1.0) : 0.0;
    const QPointF nearest = a + t * d;
    return std::hypot(p.x() - nearest.x(), p.y() - nearest.y());
}

}  // namespace ensil::ui

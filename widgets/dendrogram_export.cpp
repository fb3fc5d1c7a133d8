#include "widgets/dendrogram_export.h"

#include <QFile>
#include <QFileInfo>
#include <QFontMetricsF>
#include <QPainter>
#include <QSvgGenerator>
#include <algorithm>

#include "widgets/dendrogram_layout.h"
#include "widgets/dendrogram_painter.h"
#include "workbench/member_selection.h"

namespace ensil::ui {

bool writeDendrogramSvg(const workbench::MemberSelection& selection, const QString& path,
                        QString* error) {
    const auto fail = [&](const QString& message) {
        if (error != nullptr) *error = message;
        return false;
    };
    if (!selection.isClustered()) {
        return fail(
            QObject::tr("There is no dendrogram yet: load an ensemble and wait for its "
                        "members to be compared."));
    }
    // QSvgGenerator reports no errors: check that the file can be written first.
    {
        QFile probe(path);
        if (!probe.open(QIODevice::WriteOnly)) {
            return fail(QObject::tr("Could not write '%1': %2").arg(path, probe.errorString()));
        }
    }
    const DendrogramLayout layout(selection.tree());
    DendrogramStyle style;
    style.font.setPointSizeF(9.0);
    // One text line per leaf, so every name is drawn.
    const double leafWidth = QFontMetricsF(style.font).height() + 2.0;
    const DendrogramMargins margins = dendrogramMargins(selection, style.font, leafWidth);
    const QSizeF size(margins.left + margins.right + leafWidth * layout.memberCount(),
                      std::max(300.0, margins.top + margins.bottom + 260.0));
    QSvgGenerator generator;
    generator.setFileName(path);
    generator.setSize(size.toSize());
    generator.setViewBox(QRectF(QPointF(0, 0), size));
    generator.setTitle(QObject::tr("Dendrogram of %1 members").arg(layout.memberCount()));
    generator.setDescription(
        QObject::tr("ensil member clustering, %1 clusters").arg(selection.clusterCount()));
    QPainter painter;
    if (!painter.begin(&generator)) {
        return fail(QObject::tr("Could not write '%1'.").arg(path));
    }
    const QRectF area(QPointF(0, 0), size);
    const DendrogramFrame frame =
        dendrogramFrame(layout, selection, area, style.font, leafWidth, 0.0);
    paintDendrogram(painter, area, layout, selection, frame, style);
    painter.end();
    return QFileInfo(path).size() > 0 || fail(QObject::tr("Could not write '%1'.").arg(path));
}

}  // namespace ensil::ui

// The dendrogram as an SVG file (QSvgGenerator), drawn by the same painter as the view, with
// every member's leaf and name, on a white background. GUI thread (reads
// workbench::MemberSelection).
#pragma once

#include <QSize>
#include <QString>

namespace ensil::workbench {
class MemberSelection;
}  // namespace ensil::workbench

namespace ensil::ui {

// Returns false with a message naming the file when it cannot be written or when there is no
// merge tree to draw yet.
bool writeDendrogramSvg(const workbench::MemberSelection& selection, const QString& path,
                        QString* error = nullptr);

}  // namespace ensil::ui

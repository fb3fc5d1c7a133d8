// `ensil section FILE...|--demo --level 500hPa|--lat 45|--lon 10|--path LON,LAT:LON,LAT
// [--fill mean|spread|probability|member:N|anomaly:N|none] [--iso C] --out F.png|F.svg|F.pdf`:
// a map or a cross-section of an ensemble, with every member's contour of the isovalue in its
// cluster's colour (the clusters `ensil preprocess` and the workbench give) over a filled field
// (engine/ensemble_section.h, engine/section_painter.h). Needs no display server: it draws on
// Qt's offscreen platform. Main thread.
#pragma once

#include <QStringList>
#include <QTextStream>

namespace ensil::cli {

int runSectionCommand(const QStringList& args, QTextStream& out, QTextStream& err);

}  // namespace ensil::cli

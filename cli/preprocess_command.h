// `ensil preprocess PATH... --iso X [--var V] [--member-dim D] [--time-index I] [--clusters K]
// [--linkage L] [--error CELLS] [--no-decimation] [--no-cache] [--demo] [--json]
// [--memory-limit SIZE]`: meshes,
// attributes, similarity and clustering for one isovalue, with each stage's time. Main thread;
// no display needed.
#pragma once

#include <QStringList>
#include <QTextStream>

namespace ensil::cli {

int runPreprocessCommand(const QStringList& args, QTextStream& out, QTextStream& err);

}  // namespace ensil::cli

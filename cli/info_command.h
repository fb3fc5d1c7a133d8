// `ensil info PATH... [--var V] [--member-dim D] [--time-index I] [--json]`: prints what ensil
// sees in the files. Main thread; no display needed.
#pragma once

#include <QStringList>
#include <QTextStream>

namespace ensil::cli {

int runInfoCommand(const QStringList& args, QTextStream& out, QTextStream& err);

}  // namespace ensil::cli

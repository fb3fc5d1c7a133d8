// Runs the `ensil` command line in this process, as a user types it (without the program
// name), and keeps its exit status and what it printed.
#pragma once

#include <QString>
#include <QStringList>
#include <QTextStream>

#include "app/command_line.h"

namespace ensil::test {

struct EnsilRun {
    int code = 0;
    QString out;
    QString err;
};

inline EnsilRun runEnsil(const QStringList& args) {
    EnsilRun r;
    QTextStream out(&r.out), err(&r.err);
    r.code = app::runCommandLine(QStringList{"ensil"} + args, out, err).exitCode;
    out.flush();
    err.flush();
    return r;
}

}  // namespace ensil::test

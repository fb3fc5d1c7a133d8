// Runs the `ensil` command line in this process, as a user types it (without the program
// name), and keeps its exit status and what it printed.
#pragma once

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include "cli/command_line.h"
#include "preprocessing/clustering.h"

namespace ensil::test {

struct EnsilRun {
    int code = 0;
    QString out;
    QString err;
};

inline EnsilRun runEnsil(const QStringList& args) {
    EnsilRun r;
    QTextStream out(&r.out), err(&r.err);
    r.code = cli::runCommandLine(QStringList{"ensil"} + args, out, err).exitCode;
    out.flush();
    err.flush();
    return r;
}

// What a command printed with --json.
inline QJsonObject jsonOf(const EnsilRun& run) {
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

// The ERA5 ensemble of data assimilation members (four times) that several command tests read.
inline const QString kEra5 = QStringLiteral(ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc");

// The merge tree of `ensil preprocess --json`'s "linkage" (SciPy's rows a, b, height, size).
inline prep::MergeTree treeOfLinkageJson(const QJsonArray& linkage, int members) {
    prep::MergeTree tree;
    tree.memberCount = members;
    for (const auto row : linkage) {
        const QJsonArray r = row.toArray();
        tree.merges.push_back({r[0].toInt(), r[1].toInt(), r[2].toDouble(), r[3].toInt()});
    }
    return tree;
}

}  // namespace ensil::test

// What every subcommand does with its arguments first: parse them, answer --help, and report
// parse errors. Main thread.
#pragma once

#include <QCommandLineParser>
#include <QTextStream>
#include <exception>
#include <optional>

#include "session/setting_options.h"

namespace ensil::cli {

// Returns an exit code when the command is done (help shown: 0; bad arguments: 2), or nullopt
// when it should go on with the parsed options.
std::optional<int> parseSubcommand(QCommandLineParser& parser, const QStringList& args,
                                   const QString& name, QTextStream& out, QTextStream& err);

// The exit status for what reading or using the data threw: 2 where the data refused an argument
// the command line gave (a --bbox with no grid point, data::RegionOutsideGrid), 1 otherwise.
int dataFailureStatus(const std::exception& e);

// --clusters and --linkage, with their ranges from the one setting table, as `preprocess` and
// `section` take them.
const session::SettingOptions& clusterOptions();

}  // namespace ensil::cli

// `ensil generate`: writes the demo ensemble as a CF NetCDF file. Main thread.
#pragma once

#include <QStringList>
#include <QTextStream>

namespace ensil::cli {

int runGenerateCommand(const QStringList& args, QTextStream& out, QTextStream& err);

// Parses "NXxNYxNZ" (e.g. "256x128x16"). Returns false and leaves the outputs alone on error.
bool parseGridSize(const QString& text, std::size_t& nx, std::size_t& ny, std::size_t& nz);

}  // namespace ensil::cli

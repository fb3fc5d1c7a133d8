// Where the workbench's file dialogs start and what they show: a project is saved beside the
// data it shows unless the user saved one elsewhere before (never at "/"), and the Open dialog
// lists every format ensil reads, WRF's output files (which have no extension) included.
// Pure; GUI thread or any.
#pragma once

#include <QString>

namespace ensil::workbench {

// The path Save Project As offers: the project's own path when it has one; else
// "session.ensil" in the folder last saved into, else in the data file's folder, else in the
// home folder.
QString suggestedProjectPath(const QString& projectPath, const QString& lastFolder,
                             const QString& dataFile);

// The Open dialog's filters, ";;"-separated, the ensemble files first.
QString ensembleFileFilters();

}  // namespace ensil::workbench

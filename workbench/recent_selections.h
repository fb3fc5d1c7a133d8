// The data opened recently, kept in QSettings: the files and the choices made for them in the
// open-data dialog (variable, member dimension, time index), so that a recent entry reopens
// what was on screen, not just the same files. The file list stays under "recentFiles" (paths
// joined by newlines, newest first), as before; the choices sit beside it. GUI thread.
#pragma once

#include <QSettings>
#include <QString>
#include <vector>

#include "data/ensemble_reader.h"

namespace ensil::workbench {

struct RecentSelection {
    QString label;  // the file, or "3 files in /data/runs"
    data::DataSelection selection;
};

// Puts the selection first (replacing an entry for the same files) and keeps at most `keep`.
void rememberSelection(QSettings& settings, const data::DataSelection& selection, int keep = 10);
// Newest first.
std::vector<RecentSelection> recentSelections(const QSettings& settings);

}  // namespace ensil::workbench

// The step between choosing files and loading them: shows the open-data dialog for the files
// and answers its questions about them (variables, member dimension, time steps) from the
// headers, read on a worker thread so the window never waits for the disk or for a load that
// holds the netCDF library. GUI thread only.
#pragma once

#include <QStringList>
#include <cstddef>

class QWidget;

namespace ensil::ui {
class OpenDataDialog;
}

namespace ensil::app {

// Opens the dialog (window-modal, deleted when closed) and starts the first probe. The caller
// connects QDialog::accepted and reads OpenDataDialog::selection().
// `memoryLimit` (the workbench's) is what the dialog's size line measures the data against.
ui::OpenDataDialog* showOpenDataDialog(const QStringList& files, QWidget* parent,
                                       std::size_t memoryLimit = 0);

// Answers every probeRequested of the dialog on a worker thread. A result that arrives after
// the dialog is gone is dropped; the dialog ignores answers to superseded requests.
void answerProbesInBackground(ui::OpenDataDialog* dialog, std::size_t memoryLimit = 0);

}  // namespace ensil::app

#include "app/open_data_flow.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include "app/data_probe.h"
#include "widgets/open_data_dialog.h"

namespace ensil::app {

void answerProbesInBackground(ui::OpenDataDialog* dialog) {
    QObject::connect(dialog, &ui::OpenDataDialog::probeRequested, dialog,
                     [dialog](const data::DataSelection& selection, int request) {
                         // Owned by the dialog: closing it drops the answer instead of waiting for
                         // it.
                         auto* watcher = new QFutureWatcher<ui::DataProbe>(dialog);
                         QObject::connect(watcher, &QFutureWatcherBase::finished, dialog,
                                          [dialog, watcher, request] {
                                              dialog->showProbe(watcher->result(), request);
                                              watcher->deleteLater();
                                          });
                         watcher->setFuture(QtConcurrent::run(&probeData, selection));
                     });
}

ui::OpenDataDialog* showOpenDataDialog(const QStringList& files, QWidget* parent) {
    auto* dialog = new ui::OpenDataDialog(files, parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    answerProbesInBackground(dialog);
    dialog->requestProbe();
    dialog->open();
    return dialog;
}

}  // namespace ensil::app

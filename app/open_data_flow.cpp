#include "app/open_data_flow.h"

#include "engine/data_probe.h"
#include "widgets/open_data_dialog.h"
#include "workbench/background_job.h"

namespace ensil::app {

namespace {
// The dialog's probes, on the one job path of the workbench (BackgroundJob: a lower priority,
// throttled progress, a newer probe supersedes the running one). Owned by the dialog; closing
// it drops a probe's answer instead of waiting for it (the probe captures only values).
class ProbeJobs : public QObject {
public:
    ProbeJobs(ui::OpenDataDialog* dialog, std::size_t memoryLimit)
        : QObject(dialog), m_dialog(dialog), m_memoryLimit(memoryLimit) {}
    void answer(const data::DataSelection& selection, int request) {
        m_job.start(
            [selection, limit = m_memoryLimit](const std::stop_token&, const data::Progress&) {
                return engine::probeData(selection, limit);
            },
            [this, request](engine::DataProbe probe) { m_dialog->showProbe(probe, request); },
            [this, request](const std::exception_ptr&, bool cancelled) {
                // probeData reports problems in its result; anything else is a bug
                // worth saying, but a superseded probe is no news.
                if (cancelled) return;
                engine::DataProbe failed;
                failed.error = QObject::tr("The files could not be read.");
                m_dialog->showProbe(failed, request);
            });
    }

private:
    ui::OpenDataDialog* m_dialog;
    std::size_t m_memoryLimit;
    workbench::BackgroundJob<engine::DataProbe> m_job{
        this, workbench::BackgroundJob<engine::DataProbe>::WhenDestroyed::Abandon};
};
}  // namespace

void answerProbesInBackground(ui::OpenDataDialog* dialog, std::size_t memoryLimit) {
    auto* jobs = new ProbeJobs(dialog, memoryLimit);
    QObject::connect(dialog, &ui::OpenDataDialog::probeRequested, jobs,
                     [jobs](const data::DataSelection& selection, int request) {
                         jobs->answer(selection, request);
                     });
}

ui::OpenDataDialog* showOpenDataDialog(const QStringList& files, QWidget* parent,
                                       std::size_t memoryLimit) {
    auto* dialog = new ui::OpenDataDialog(files, parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    answerProbesInBackground(dialog, memoryLimit);
    dialog->requestProbe();
    dialog->open();
    return dialog;
}

}  // namespace ensil::app

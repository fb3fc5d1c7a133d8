// Opening data: the demo or files read in the background (engine::readEnsembleOverview on a
// BackgroundJob) with progress and cancel, the ensemble on screen kept until the new one is
// ready and kept when loading fails; a failure said in the status bar and a message box, and a
// file without a member dimension answered by asking which dimension stands in for members.
// Part of MainWindow.
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>
#include <optional>

#include "app/main_window.h"
#include "data/error.h"
#include "engine/ensemble_overview.h"
#include "engine/session_renderer.h"
#include "engine/streaming_run.h"
#include "widgets/ensemble_info_panel.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"

namespace ensil::app {
namespace {

QString messageOf(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);  // unwrapped by BackgroundJob
    } catch (const std::bad_alloc&) {
        return QObject::tr("not enough memory to load the ensemble");
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    } catch (...) {
        return QStringLiteral("unknown error");
    }
}

// The reader's typed error, if that is what the worker threw.
std::optional<data::Error> dataErrorOf(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);  // unwrapped by BackgroundJob
    } catch (const data::Error& e) {
        return e;
    } catch (...) {
        return std::nullopt;
    }
}

}  // namespace

void MainWindow::loadDemo(const data::DemoEnsembleParams& params) {
    m_requested.reset();
    m_requestedDemo = params;

    startLoading(
        tr("Generating the demo ensemble (%1 members, %2 x %3 x %4)...")
            .arg(params.members)
            .arg(params.nx)
            .arg(params.ny)
            .arg(params.nz),
        [params] { return engine::demoSourceKey(params); },
        [params](const std::stop_token& stop, const data::Progress& progress) {
            return engine::WorkbenchEnsemble{
                data::makeDemoEnsemble(params, stop, progress).ensemble, {}, {}};
        });
}

void MainWindow::openFiles(const data::DataSelection& selection) {
    const QString name = selection.paths.size() == 1
                             ? QFileInfo(QString::fromStdString(selection.paths.front())).fileName()
                             : tr("%1 files").arg(selection.paths.size());
    rememberRecent(selection);
    m_requested = selection;
    m_requestedDemo.reset();
    startLoading(
        tr("Reading %1...").arg(name), [selection] { return data::sourceIdentity(selection); },
        [selection, limit = memoryLimit()](const std::stop_token& stop,
                                           const data::Progress& progress) {
            return engine::readForWorkbench(selection, limit, stop, progress);
        });
}

std::size_t MainWindow::memoryLimit() const {
    return m_memoryLimit != 0 ? m_memoryLimit : engine::defaultMemoryLimit();
}

void MainWindow::startLoading(const QString& what, std::function<std::string()> identify,
                              engine::WorkbenchRead read) {
    setBusy(what);
    if (!m_overview) {
        m_info->showMessage(tr("Loading..."));
        m_view->setPlaceholderText(what);
    }
    forgetTimeSteps();  // other data: the steps read ahead are not its
    m_loader.start(
        [read = std::move(read), identify = std::move(identify)](const std::stop_token& stop,
                                                                 const data::Progress& progress) {
            return engine::readEnsembleOverview(read, identify, stop, progress);
        },
        [this](engine::EnsembleOverview overview) {
            showOverview(std::make_unique<engine::EnsembleOverview>(std::move(overview)));
        },
        [this](const std::exception_ptr& error, bool cancelled) { onLoadFailed(error, cancelled); },
        [this](double f) { showProgress(f); });
}

void MainWindow::cancelLoading() {
    m_loader.cancel();
    m_surfaceExport.cancel();
    if (m_session != nullptr) m_session->cancel();
}

void MainWindow::onLoadFailed(const std::exception_ptr& error, bool cancelled) {
    const bool retrying = !cancelled && error && m_requested;  // see askForMemberDimension
    if (!retrying) m_pendingProject.reset();  // a project whose data did not load is not applied
    if (cancelled || !error) {
        setIdle(tr("Loading cancelled"));
        if (!m_overview) {
            m_info->showMessage(tr("No ensemble loaded (loading was cancelled)."));
            m_view->setPlaceholderText({});
        }
        return;
    }
    const auto dataError = dataErrorOf(error);
    if (dataError && dataError->kind() == data::ErrorKind::MemberDimensionNotFound &&
        !dataError->choices().empty() && m_requested) {
        askForMemberDimension(*dataError);
        return;
    }
    const QString message = messageOf(error);
    setIdle(tr("Loading failed: %1").arg(message));
    if (!m_overview) {
        m_view->setPlaceholderText(tr("Could not open the ensemble: %1\n\n").arg(message) +
                                   ui::SilhouetteView::defaultPlaceholder());
    }
    if (!m_overview) m_info->showMessage(tr("Loading failed: %1").arg(message));
    // Not modal: the window stays usable, and scripted sessions are not blocked.
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open the ensemble"), message,
                                QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
    emit loadingFailed(message);
}

void MainWindow::askForMemberDimension(const data::Error& error) {
    // Many files hold one run over time or months: let the user say which dimension stands in
    // for members instead of failing. Not modal, so scripted sessions can answer it too.
    QStringList choices;
    for (const auto& c : error.choices()) choices << QString::fromStdString(c);
    const QString file = QFileInfo(QString::fromStdString(m_requested->paths.front())).fileName();
    setIdle(tr("%1 has no member dimension: choose one").arg(file));
    if (!m_overview) m_info->showMessage(tr("Waiting for the choice of member dimension."));
    auto* dialog = new QInputDialog(this);
    dialog->setObjectName(QStringLiteral("memberDimensionDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Which dimension holds the members?"));
    dialog->setLabelText(
        tr("ensil found no ensemble member dimension in %1.\n\nIf one of its other dimensions "
           "(such as forecast times or months) stands in for members, choose it:")
            .arg(file));
    dialog->setComboBoxItems(choices);
    dialog->setComboBoxEditable(false);
    const data::DataSelection retry = *m_requested;
    connect(dialog, &QInputDialog::textValueSelected, this, [this, retry](const QString& dim) {
        data::DataSelection chosen = retry;
        chosen.memberDimension = dim.toStdString();
        openFiles(chosen);
    });
    dialog->open();
}

}  // namespace ensil::app

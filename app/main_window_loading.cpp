// What the window shows of opening data (workbench::Workbench reads them in the background, with
// progress and cancel, keeping the ensemble on screen until the new one is ready): the status
// bar and the placeholder while reading, a failure in the status bar and a message box, and a
// file without a member dimension answered by asking which dimension stands in for members.
// Part of MainWindow.
#include <QInputDialog>
#include <QMessageBox>

#include "app/main_window.h"
#include "widgets/ensemble_info_panel.h"
#include "widgets/silhouette_view.h"
#include "workbench/workbench.h"

namespace ensil::app {

void MainWindow::bindOpening() {
    connect(m_workbench, &workbench::Workbench::openingStarted, this, [this](const QString& what) {
        setBusy(what);
        if (overview() == nullptr) {
            m_info->showMessage(tr("Loading..."));
            m_view->setPlaceholderText(what);
        }
        m_stepChanging = false;  // other data: no step of the last data is on its way
    });
    connect(m_workbench, &workbench::Workbench::progressed, this, &MainWindow::showProgress);
    connect(m_workbench, &workbench::Workbench::dataArrived, this, &MainWindow::showOverview);
    connect(m_workbench, &workbench::Workbench::openingCancelled, this, [this] {
        setIdle(tr("Loading cancelled"));
        if (overview() == nullptr) {
            m_info->showMessage(tr("No ensemble loaded (loading was cancelled)."));
            m_view->setPlaceholderText({});
        }
    });
    connect(m_workbench, &workbench::Workbench::openingFailed, this,
            &MainWindow::showOpeningFailed);
    connect(m_workbench, &workbench::Workbench::memberDimensionAsked, this,
            &MainWindow::askForMemberDimension);
    connect(m_workbench, &workbench::Workbench::projectOpened, this,
            &MainWindow::showOpenedProject);
}

void MainWindow::loadDemo(const data::DemoEnsembleParams& params) { m_workbench->loadDemo(params); }

void MainWindow::openFiles(const data::DataSelection& selection) {
    rememberRecent(selection);
    m_workbench->openFiles(selection);
}

void MainWindow::setMemoryLimit(std::size_t bytes) { m_workbench->setMemoryLimit(bytes); }

std::size_t MainWindow::memoryLimit() const { return m_workbench->memoryLimit(); }

const engine::EnsembleOverview* MainWindow::overview() const { return m_workbench->overview(); }

bool MainWindow::isLoading() const { return m_workbench->isOpening(); }

void MainWindow::cancelLoading() {
    m_workbench->cancel();
    m_surfaceExport.cancel();
}

void MainWindow::showOpeningFailed(const QString& message) {
    setIdle(tr("Loading failed: %1").arg(message));
    if (overview() == nullptr) {
        m_view->setPlaceholderText(tr("Could not open the ensemble: %1\n\n").arg(message) +
                                   ui::SilhouetteView::defaultPlaceholder());
        m_info->showMessage(tr("Loading failed: %1").arg(message));
    }
    // Not modal: the window stays usable, and scripted sessions are not blocked.
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open the ensemble"), message,
                                QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
    emit loadingFailed(message);
}

void MainWindow::askForMemberDimension(const QString& file, const QStringList& choices) {
    // Many files hold one run over time or months: let the user say which dimension stands in
    // for members instead of failing. Not modal, so scripted sessions can answer it too.
    setIdle(tr("%1 has no member dimension: choose one").arg(file));
    if (overview() == nullptr)
        m_info->showMessage(tr("Waiting for the choice of member dimension."));
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
    const data::DataSelection retry = *m_workbench->files();
    connect(dialog, &QInputDialog::textValueSelected, this, [this, retry](const QString& dim) {
        data::DataSelection chosen = retry;
        chosen.memberDimension = dim.toStdString();
        openFiles(chosen);
    });
    dialog->open();
}

}  // namespace ensil::app

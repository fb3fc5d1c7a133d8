// Project files in the main window: what a project captures of the session, opening one
// (validated whole first, missing data files located by the user, then applied once its data
// has loaded), saving (atomic), and the recent projects menu.
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <algorithm>

#include "app/main_window.h"
#include "session/project_file.h"
#include "session/session_camera.h"
#include "session/session_model.h"
#include "widgets/cluster_panel.h"
#include "widgets/cutting_plane_panel.h"
#include "widgets/render_panel.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "workbench/dialog_paths.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"
#include "workbench/workbench.h"

namespace ensil::app {
namespace {
constexpr int kRecentProjects = 10;
const QString kRecentKey = QStringLiteral("recentProjects");
const QString kFilter = QStringLiteral("ensil projects (*.ensil)");
}  // namespace

void MainWindow::createProjectActions(QMenu* file) {
    file->addAction(tr("Open &Project..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O), this,
                    [this] {
                        const QString path = QFileDialog::getOpenFileName(
                            this, tr("Open Project"),
                            QSettings().value("project/lastFolder").toString(), kFilter);
                        if (!path.isEmpty()) openProject(path);
                    });
    m_recentProjectsMenu = file->addMenu(tr("Recent Projects"));
    rebuildRecentProjectsMenu();
    file->addAction(tr("&Save Project"), QKeySequence::Save, this, [this] {
        if (projectPath().isEmpty()) {
            chooseProjectPathAndSave();
        } else {
            saveProjectReporting(projectPath());
        }
    });
    file->addAction(tr("Save Project &As..."), QKeySequence::SaveAs, this,
                    &MainWindow::chooseProjectPathAndSave);
}

void MainWindow::chooseProjectPathAndSave() {
    const data::DataSelection& shown = m_model->state().data;
    const QString dataFile =
        shown.paths.empty() ? QString() : QString::fromStdString(shown.paths.front());
    QString path = QFileDialog::getSaveFileName(
        this, tr("Save Project"),
        workbench::suggestedProjectPath(
            projectPath(), QSettings().value("project/lastFolder").toString(), dataFile),
        kFilter);
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".ensil");
    saveProjectReporting(path);
}

void MainWindow::saveProjectReporting(const QString& path) {
    QString error;
    if (!saveProjectTo(path, &error)) QMessageBox::warning(this, tr("Project not saved"), error);
}

bool MainWindow::saveProjectTo(const QString& path, QString* error) {
    if (overview() == nullptr) {
        if (error != nullptr) *error = tr("There is nothing to save yet: load an ensemble first.");
        return false;
    }
    try {
        session::saveProject(captureSession(), path);
    } catch (const session::ProjectError& e) {
        if (error != nullptr) *error = QString::fromStdString(e.what());
        return false;
    }
    m_workbench->setProjectPath(path);
    rememberRecentProject(path);
    statusBar()->showMessage(tr("Saved the project to %1").arg(path), 4000);
    updateWindowTitle();
    return true;
}

void MainWindow::showAndOpen(const data::DataSelection& selection) {
    const auto& paths = selection.paths;
    const bool isProject = paths.size() == 1 &&
                           QString::fromStdString(paths.front()).endsWith(QLatin1String(".ensil"));
    std::optional<session::SessionState> project;
    if (isProject) {
        project = readProject(QString::fromStdString(paths.front()));
        // The project's layout is restored before the window is shown. Restoring a layout
        // into a shown window whose own remembered layout (the constructor's) is still
        // waiting for the window manager to maximise it leaves Qt 6.4's main window layout
        // with dock items it has freed: the next layout pass crashed (issue 37).
        if (project && !project->windowState.isEmpty()) restoreState(project->windowState);
    }
    // The first run has no saved layout: the view and its three docks want the whole screen.
    if (hasSavedLayout()) {
        show();
    } else {
        showMaximized();
    }
    if (isProject) {
        if (project) openReadProject(std::move(*project), QString::fromStdString(paths.front()));
    } else if (paths.empty()) {
        loadDemo();
    } else {
        openFiles(selection);
    }
}

bool MainWindow::openProject(const QString& path) {
    std::optional<session::SessionState> project = readProject(path);
    if (!project) return false;
    if (!project->windowState.isEmpty()) restoreState(project->windowState);
    return openReadProject(std::move(*project), path);
}

std::optional<session::SessionState> MainWindow::readProject(const QString& path) {
    try {
        return session::loadProject(path);
    } catch (const session::ProjectError& e) {
        const QString message = QString::fromStdString(e.what());
        auto* box =
            new QMessageBox(QMessageBox::Warning, tr("Cannot open the project"),
                            message + tr("\n\nNothing was changed."), QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        emit loadingFailed(message);
        return std::nullopt;
    }
}

bool MainWindow::openReadProject(session::SessionState project, const QString& path) {
    // Data files that moved: the user points at them, or nothing changes.
    for (std::string& file : project.data.paths) {
        const QString missing = QString::fromStdString(file);
        if (QFileInfo::exists(missing)) continue;
        const QString found = m_locateMissingFile ? m_locateMissingFile(missing) : QString();
        if (found.isEmpty()) {
            const QString message = tr("The project's data file %1 was not found; opening was "
                                       "cancelled and nothing changed.")
                                        .arg(missing);
            setIdle(message);
            emit loadingFailed(message);
            return false;
        }
        file = found.toStdString();
    }
    QSettings().setValue("project/lastFolder", QFileInfo(path).absolutePath());
    if (!project.demo) rememberRecent(project.data);
    m_workbench->openProject(std::move(project), path);
    return true;
}

QString MainWindow::locateMissingFileWithDialog(const QString& missing) {
    QMessageBox::information(
        this, tr("Data file not found"),
        tr("The project's data file\n%1\nis not there any more. Please show where it is now.")
            .arg(missing));
    return QFileDialog::getOpenFileName(this, tr("Locate %1").arg(QFileInfo(missing).fileName()),
                                        QFileInfo(missing).absolutePath());
}

float MainWindow::viewAspect() const {
    return static_cast<float>(m_view->width()) / static_cast<float>(std::max(1, m_view->height()));
}

void MainWindow::applyPendingProjectCamera() {
    session::placeCamera(m_workbench->pendingProject()->camera, m_view->renderer());
}

QString MainWindow::projectPath() const { return m_workbench->projectPath(); }

void MainWindow::showOpenedProject(const QString& path) {
    rememberRecentProject(path);
    updateWindowTitle();
    emit projectOpened();
}

void MainWindow::rememberRecentProject(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(kRecentKey).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    while (recent.size() > kRecentProjects) recent.removeLast();
    settings.setValue(kRecentKey, recent);
    rebuildRecentProjectsMenu();
}

void MainWindow::rebuildRecentProjectsMenu() {
    if (m_recentProjectsMenu == nullptr) return;
    m_recentProjectsMenu->clear();
    const QStringList recent = QSettings().value(kRecentKey).toStringList();
    for (const QString& path : recent) {
        m_recentProjectsMenu->addAction(QFileInfo(path).fileName() + QStringLiteral("  (") +
                                            QFileInfo(path).absolutePath() + QLatin1Char(')'),
                                        this, [this, path] { openProject(path); });
    }
    m_recentProjectsMenu->setEnabled(!recent.isEmpty());
}

void MainWindow::updateWindowTitle() {
    if (overview() == nullptr) return;
    const data::Ensemble& e = *overview()->ensemble;
    QString title = QStringLiteral("%1 - %2").arg(QString::fromStdString(e.variable),
                                                  QString::fromStdString(e.source));
    if (!projectPath().isEmpty()) title = QFileInfo(projectPath()).fileName() + " - " + title;
    setWindowTitle(title + QStringLiteral(" - ensil"));
}

}  // namespace ensil::app

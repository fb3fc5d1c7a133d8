#include "app/main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QScopedValueRollback>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QToolButton>
#include <chrono>
#include <map>

#include "app/open_data_flow.h"
#include "data/error.h"
#include "engine/ensemble_facts.h"
#include "engine/floor_map.h"
#include "engine/picture_title.h"
#include "engine/session_renderer.h"
#include "geo/map_projection.h"
#include "session/session_model.h"
#include "session/version.h"
#include "session/view_presets.h"
#include "widgets/cluster_panel.h"
#include "widgets/cluster_timeline.h"
#include "widgets/ensemble_info_panel.h"
#include "widgets/frame_paced_repaints.h"
#include "widgets/open_data_dialog.h"
#include "widgets/render_toolbar.h"
#include "widgets/sections_panel.h"
#include "widgets/silhouette_view.h"
#include "widgets/time_bar.h"
#include "workbench/dialog_paths.h"
#include "workbench/isovalue_session.h"
#include "workbench/point_description.h"
#include "workbench/recent_selections.h"
#include "workbench/step_cluster_strip.h"
#include "workbench/time_steps.h"
#include "workbench/workbench.h"

namespace ensil::app {
namespace {
constexpr int kProgressSteps = 1000;
// How long the isovalue's slider, spin box and marker may wait for a preview frame to be drawn
// with (ui::FramePacedRepaints): ten repaints a second at the least.
constexpr std::chrono::milliseconds kLongestScrubRepaintWait{100};

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_view(new ui::SilhouetteView),
      // The cache the command line uses too (a mesh built by `ensil preprocess` is found here).
      m_workbench(new workbench::Workbench(
          m_view, QString::fromStdString(engine::defaultMeshCacheDirectory()), this)),
      m_model(m_workbench->model()),
      m_selection(m_workbench->selection()),
      m_session(m_workbench->isovalue()),
      m_timeSteps(m_workbench->timeSteps()) {
    setWindowTitle(QStringLiteral("ensil"));
    setCentralWidget(m_view);
    setDockOptions(AnimatedDocks | AllowNestedDocks | AllowTabbedDocks);
    createDocks();
    createStatusBar();
    createVariableChoice();
    createToolbar();
    createRenderDocks();
    createAnimation();
    createTimeBar();
    createMenus();
    linkPanels();
    bindOpening();
    // Last: everything the bindings show the session in exists now.
    bindSession();
    restoreRenderSettings();
    connect(m_view, &ui::SilhouetteView::renderingFailed, this, [this](const QString& message) {
        QMessageBox::critical(this, tr("ensil cannot draw"),
                              tr("The 3D view needs OpenGL 4.1 (core profile), which this "
                                 "display does not provide.\n\n%1\n\nUpdate the graphics "
                                 "driver, or run ensil on a machine with OpenGL 4.1.")
                                  .arg(message));
    });

    m_locateMissingFile = [this](const QString& missing) {
        return locateMissingFileWithDialog(missing);
    };
    QSettings settings;
    resize(1400, 900);
    m_hasSavedLayout = settings.contains(QStringLiteral("window/state"));
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
}

MainWindow::~MainWindow() {
    // Closing hides the docks before they are deleted; what their hiding says must not reach
    // this window half destroyed.
    const auto sections = findChild<QDockWidget*>(QStringLiteral("sectionsDock"));
    if (sections != nullptr) disconnect(sections, nullptr, this, nullptr);
    disconnect(m_sections, nullptr, this, nullptr);
    // The workbench outlives this destructor (a child, deleted after it): what it says now
    // must not reach this window half destroyed, and its workers must not outlive the window.
    disconnect(m_workbench, nullptr, this, nullptr);
    m_workbench->cancel();
}

void MainWindow::createDocks() {
    m_info = new ui::EnsembleInfoPanel;
    auto* dock = new QDockWidget(tr("Ensemble"), this);
    dock->setObjectName(QStringLiteral("ensembleDock"));
    // Scrolled: the facts and notes (a streamed ensemble's, several warnings) can be longer
    // than the tabbed dock is high, and a form layout would clip them.
    auto* scroll = new QScrollArea(dock);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(m_info);
    dock->setWidget(scroll);
    addDockWidget(Qt::LeftDockWidgetArea, dock);
    m_info->showMessage(tr("No ensemble loaded."));
    createPanels();
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open..."), QKeySequence::Open, this, &MainWindow::chooseFiles);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
    file->addAction(tr("Open &Demo Ensemble"), this, [this] { loadDemo(); });
    file->addSeparator();
    createProjectActions(file);
    file->addSeparator();
    QAction* screenshot =
        file->addAction(tr("Save &Screenshot..."), this, &MainWindow::chooseScreenshot);
    screenshot->setShortcut(QKeySequence(Qt::Key_F12));
    addExportActions(file);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
    m_resetCameraAction = new QAction(tr("&Reset Camera"), this);
    m_resetCameraAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    connect(m_resetCameraAction, &QAction::triggered, m_view, &ui::SilhouetteView::resetCamera);
    // Views a meteorologist asks for (session/view_presets.h): a map, north up, from straight
    // above, and the views from the four sides; Ctrl+T for the map, Alt+Shift and the compass
    // letter for the sides.
    const std::map<std::string_view, QKeySequence> shortcuts{
        {"top", QKeySequence(Qt::CTRL | Qt::Key_T)},
        {"north", QKeySequence(Qt::ALT | Qt::SHIFT | Qt::Key_N)},
        {"south", QKeySequence(Qt::ALT | Qt::SHIFT | Qt::Key_S)},
        {"east", QKeySequence(Qt::ALT | Qt::SHIFT | Qt::Key_E)},
        {"west", QKeySequence(Qt::ALT | Qt::SHIFT | Qt::Key_W)}};
    for (const session::ViewPreset& preset : session::viewPresets()) {
        auto* action = new QAction(tr(std::string(preset.label).c_str()), this);
        action->setObjectName(QStringLiteral("view_%1").arg(QLatin1String(preset.id)));
        if (const auto key = shortcuts.find(preset.id); key != shortcuts.end()) {
            action->setShortcut(key->second);
        }
        connect(action, &QAction::triggered, this, [this, &preset] { lookFrom(preset); });
        m_viewPresetActions << action;
    }
    createEditMenu();

    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->addAction(m_resetCameraAction);
    viewMenu->addActions(m_viewPresetActions);
    QAction* fullScreen = viewMenu->addAction(tr("&Full Screen"));
    fullScreen->setShortcut(QKeySequence::FullScreen);
    fullScreen->setCheckable(true);
    connect(fullScreen, &QAction::toggled, this,
            [this](bool on) { on ? showFullScreen() : showNormal(); });
    // On a slow renderer (software OpenGL), moving the camera draws at a lower resolution.
    QAction* adaptive = viewMenu->addAction(tr("Lower Resolution While &Moving"));
    adaptive->setCheckable(true);
    adaptive->setChecked(
        QSettings().value(QStringLiteral("view/adaptiveResolution"), true).toBool());
    m_view->setAdaptiveResolution(adaptive->isChecked());
    connect(adaptive, &QAction::toggled, this, [this](bool on) {
        m_view->setAdaptiveResolution(on);
        QSettings().setValue(QStringLiteral("view/adaptiveResolution"), on);
    });
    viewMenu->addSeparator();
    viewMenu->addActions(m_modeActions);
    viewMenu->addAction(m_planeAction);
    viewMenu->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        viewMenu->addAction(dock->toggleViewAction());
    }

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About ensil"), this, [this] {
        QMessageBox::about(this, tr("About ensil"),
                           tr("<b>ensil %1</b><p>Ensemble silhouettes: ensembles of 3D "
                              "isosurfaces drawn as screen-space silhouettes, after Demir, "
                              "Kehrer and Westermann.</p>")
                               .arg(QStringLiteral(ENSIL_VERSION)));
    });
}

void MainWindow::createToolbar() {
    m_toolbar = new ui::RenderToolbar(this);
    addToolBar(Qt::TopToolBarArea, m_toolbar);
    m_scrubRepaints = new ui::FramePacedRepaints(m_toolbar, m_view, kLongestScrubRepaintWait, this);
    connect(m_session, &workbench::IsovalueSession::started, this, &MainWindow::setBusy);
    connect(m_session, &workbench::IsovalueSession::progressed, this,
            [this](double f) { m_progress->setValue(static_cast<int>(f * kProgressSteps)); });
    connect(m_session, &workbench::IsovalueSession::finished, this, &MainWindow::showBuiltSurfaces);
    connect(m_session, &workbench::IsovalueSession::failed, this, &MainWindow::setIdle);
}

void MainWindow::showProgress(double fraction) {
    m_progress->setValue(static_cast<int>(fraction * kProgressSteps));
}

void MainWindow::createStatusBar() {
    m_statusText = new QLabel(this);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, kProgressSteps);
    m_progress->setMaximumWidth(220);
    m_progress->setTextVisible(false);
    m_cancel = new QToolButton(this);
    m_cancel->setText(tr("Cancel"));
    // Esc belongs to Edit > Clear Selection, which stops the work in progress first.
    m_cancel->setToolTip(tr("Stop the work in progress (Esc)"));
    connect(m_cancel, &QToolButton::clicked, this, &MainWindow::cancelLoading);
    statusBar()->addWidget(m_statusText, 1);
    m_pointText = new QLabel(this);
    m_pointText->setObjectName(QStringLiteral("pointText"));
    statusBar()->addPermanentWidget(m_pointText);
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_cancel);
    setIdle(tr("Ready"));
}

void MainWindow::setBusy(const QString& what) {
    m_statusText->setText(what);
    m_progress->setValue(0);
    m_progress->setVisible(true);
    m_cancel->setVisible(true);
}

void MainWindow::setIdle(const QString& message) {
    m_statusText->setText(message);
    m_progress->setVisible(false);
    m_cancel->setVisible(false);
}

void MainWindow::chooseFiles() {
    QSettings settings;
    const QStringList files = QFileDialog::getOpenFileNames(
        this, tr("Open Ensemble (one file with members, or one file per member)"),
        settings.value(QStringLiteral("open/lastFolder")).toString(),
        workbench::ensembleFileFilters());
    if (files.isEmpty()) return;
    settings.setValue(QStringLiteral("open/lastFolder"), QFileInfo(files.front()).absolutePath());
    chooseData(files);
}

ui::OpenDataDialog* MainWindow::chooseData(const QStringList& files) {
    ui::OpenDataDialog* dialog = showOpenDataDialog(files, this, memoryLimit());
    connect(dialog, &QDialog::accepted, this, [this, dialog] { openFiles(dialog->selection()); });
    return dialog;
}

void MainWindow::rememberRecent(const data::DataSelection& selection) {
    QSettings settings;
    workbench::rememberSelection(settings, selection);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    m_recentMenu->clear();
    const std::vector<workbench::RecentSelection> recent = workbench::recentSelections(QSettings());
    for (const workbench::RecentSelection& entry : recent) {
        m_recentMenu->addAction(entry.label, this,
                                [this, selection = entry.selection] { openFiles(selection); });
    }
    m_recentMenu->setEnabled(!recent.empty());
}

void MainWindow::showOverview() {
    const engine::EnsembleOverview& overview = *m_workbench->overview();
    const data::Ensemble& e = *overview.ensemble;
    gl::Renderer& renderer = m_view->renderer();
    renderer.setGrid(e.grid);
    titleTheView(e);
    // The map spans its own range: the mean's column maxima cover only part of the values.
    showFloor(m_model->state().render);
    m_lastHoveredMember = -1;
    showSection();
    showSpread();
    renderer.setMapLines(overview.mapLines);
    m_mapProjection =
        std::make_unique<geo::MapProjection>(geo::MapProjection::forGrid(e.grid, e.gridMapping));
    m_info->showFacts(engine::ensembleFacts(overview));
    offerVariables();
    // The data's time steps, as the workbench's strip has them.
    const QStringList& times = m_workbench->strip()->labels();
    const auto& files = m_workbench->files();
    m_timeBar->setSteps(times, files ? static_cast<int>(files->timeIndex) : 0);
    // Time controls only for data with time steps.
    m_timeBar->setVisible(times.size() > 1);
    if (auto* dock = findChild<QDockWidget*>(QStringLiteral("clusterTimelineDock"))) {
        dock->setVisible(times.size() > 1);
    }
    m_view->setMemberNames(memberNames());
    const prep::FieldStatistics& stats = overview.statistics;
    const int members = static_cast<int>(e.memberCount());
    m_toolbar->setMemberCount(members, session::defaultClusters(members));
    showIsovalueRange(overview.defaultIsovalue);
    m_toolbar->setIsovalueHistogram(stats.histogram);
    updatePlaneBox();
    {
        // The session of this data: a project's, or the default isovalue (the toolbar shows
        // it, rounded to its precision: what gets built) and clusters; one rebuild below.
        const QScopedValueRollback showing(m_showingNewData, true);
        m_workbench->startSessionOfNewData(static_cast<float>(m_toolbar->isovalue()));
        if (m_workbench->pendingProject() != nullptr) applyPendingProjectCamera();
    }
    updateWindowTitle();
    const data::Grid& grid = overview.streamed ? overview.streamed->description.grid : e.grid;
    setIdle(tr("%1: %2 members of %3 on %4 x %5 x %6%7")
                .arg(QString::fromStdString(e.source))
                .arg(e.memberCount())
                .arg(QString::fromStdString(e.variable))
                .arg(grid.nx())
                .arg(grid.ny())
                .arg(grid.nz())
                .arg(overview.streamed
                         ? tr(", larger than the memory budget: read in slabs (see Ensemble)")
                         : QString()));
    emit ensembleLoaded();
    m_workbench->buildFirstSurfaces();
}

void MainWindow::closeEvent(QCloseEvent* event) {
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    rememberRenderSettings();
    QMainWindow::closeEvent(event);
}

void MainWindow::lookFrom(const session::ViewPreset& preset) {
    // The projection first (the map view is orthographic), then the camera fitted to the box.
    m_model->update([&preset](session::SessionState& s) { session::lookFrom(preset, s.camera); });
    m_view->lookFrom(preset.azimuth, preset.elevation);
}

void MainWindow::showFloor(const gl::RenderSettings& settings) {
    if (overview() == nullptr) return;
    m_view->renderer().setFloorMap(engine::sceneFloor(sceneData(), settings));
}

}  // namespace ensil::app

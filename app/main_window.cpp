#include "app/main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
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
#include <cmath>
#include <limits>
#include <map>

#include "app/open_data_flow.h"
#include "data/error.h"
#include "engine/ensemble_facts.h"
#include "engine/floor_map.h"
#include "engine/picture_title.h"
#include "engine/session_renderer.h"
#include "engine/streaming_run.h"
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
#include "workbench/time_steps.h"

namespace ensil::app {
namespace {
constexpr int kProgressSteps = 1000;
// How long the isovalue's slider, spin box and marker may wait for a preview frame to be drawn
// with (ui::FramePacedRepaints): ten repaints a second at the least.
constexpr std::chrono::milliseconds kLongestScrubRepaintWait{100};

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

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_view(new ui::SilhouetteView),
      m_timeSteps(new workbench::TimeSteps(this)),
      m_model(new session::SessionModel(this)) {
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
    // A worker must not outlive the window it reports to.
    m_loader.cancel();
    m_loader.wait();
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
    // The cache the command line uses too (a mesh built by `ensil preprocess` is found here).
    m_session = new workbench::IsovalueSession(
        m_view, m_selection, QString::fromStdString(engine::defaultMeshCacheDirectory()), this);
    m_session->setContextSurfacesWanted(m_model->state().render.drawsContextSurfaces());
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

engine::EnsembleOverview MainWindow::loadOverview(const EnsembleSource& source,
                                                  const std::function<std::string()>& identify,
                                                  const std::stop_token& stop,
                                                  const data::Progress& progress,
                                                  const engine::SameDataParts* sameData) {
    engine::WorkbenchEnsemble loaded =
        source(stop, [&](double f) { data::report(progress, 0.6 * f); });
    // As the command line does: no NaN distance of theirs may reach the clustering.
    std::vector<std::string> withoutData = data::leaveOutMembersWithoutData(loaded.ensemble);
    engine::EnsembleOverview overview = engine::buildEnsembleOverview(
        std::make_shared<const data::Ensemble>(std::move(loaded.ensemble)), stop,
        [&](double f) { data::report(progress, 0.6 + 0.4 * f); }, sameData);
    overview.sourceKey = identify() + data::membersWithoutDataKey(withoutData);
    overview.membersWithoutData = std::move(withoutData);
    overview.variables = std::move(loaded.variables);
    if (loaded.streamed) {
        overview.streamed =
            std::make_shared<const engine::StreamedSource>(std::move(*loaded.streamed));
    }
    return overview;
}

void MainWindow::startLoading(const QString& what, std::function<std::string()> identify,
                              EnsembleSource source) {
    setBusy(what);
    if (!m_overview) {
        m_info->showMessage(tr("Loading..."));
        m_view->setPlaceholderText(what);
    }
    forgetTimeSteps();  // other data: the steps read ahead are not its
    m_loader.start(
        [source = std::move(source), identify = std::move(identify)](
            const std::stop_token& stop, const data::Progress& progress) {
            return loadOverview(source, identify, stop, progress);
        },
        [this](engine::EnsembleOverview overview) {
            showOverview(std::make_unique<engine::EnsembleOverview>(std::move(overview)));
        },
        [this](const std::exception_ptr& error, bool cancelled) { onLoadFailed(error, cancelled); },
        [this](double f) { m_progress->setValue(static_cast<int>(f * kProgressSteps)); });
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

void MainWindow::showOverview(std::unique_ptr<engine::EnsembleOverview> overview) {
    m_overview = std::move(overview);
    m_historyStartsAfresh = true;
    if (!m_pendingProject) m_projectPath.clear();  // other data: no longer that project
    const data::Ensemble& e = *m_overview->ensemble;
    gl::Renderer& renderer = m_view->renderer();
    renderer.setGrid(e.grid);
    titleTheView(e);
    // The map spans its own range: the mean's column maxima cover only part of the values.
    showFloor(m_model->state().render);
    m_lastHoveredMember = -1;
    showSection();
    showSpread();
    renderer.setMapLines(m_overview->mapLines);
    m_mapProjection =
        std::make_unique<geo::MapProjection>(geo::MapProjection::forGrid(e.grid, e.gridMapping));
    m_info->showFacts(engine::ensembleFacts(*m_overview));
    offerVariables();
    m_session->setEnsemble(m_overview->ensemble, m_overview->moments, m_overview->sourceKey,
                           m_overview->streamed);
    QStringList times;
    for (const std::string& label : e.timeSteps.labels) times << QString::fromStdString(label);
    m_timeBar->setSteps(times, m_requested ? static_cast<int>(m_requested->timeIndex) : 0);
    resetStepClusters(times);
    // Time controls only for data with time steps.
    m_timeBar->setVisible(times.size() > 1);
    if (auto* dock = findChild<QDockWidget*>(QStringLiteral("clusterTimelineDock"))) {
        dock->setVisible(times.size() > 1);
    }
    m_view->setMemberNames(memberNames());
    const prep::FieldStatistics& stats = m_overview->statistics;
    const int members = static_cast<int>(e.memberCount());
    m_toolbar->setMemberCount(members, session::defaultClusters(members));
    showIsovalueRange(m_overview->defaultIsovalue);
    m_toolbar->setIsovalueHistogram(stats.histogram);
    updatePlaneBox();
    {
        // The session of this data: a project's, or the default isovalue (the toolbar shows
        // it, rounded to its precision: what gets built) and clusters; one rebuild below.
        const QScopedValueRollback showing(m_showingNewData, true);
        const auto shownIsovalue = static_cast<float>(m_toolbar->isovalue());
        m_model->update([&](session::SessionState& s) {
            if (m_pendingProject) {
                s = *m_pendingProject;
                // Its members are shown once their surfaces are built (applyPendingProject).
                s.hiddenMembers.clear();
                s.hiddenClusters.clear();
                s.selection.clear();
            }
            s.demo = m_requestedDemo.has_value();
            s.demoParams = m_requestedDemo.value_or(data::DemoEnsembleParams{});
            s.data = m_requested.value_or(data::DataSelection{});
            if (!m_pendingProject || !s.isovalue) s.isovalue = shownIsovalue;
            s.clusters = m_pendingProject ? std::clamp(s.clusters, 1, members)
                                          : session::defaultClusters(members);
        });
        if (m_pendingProject) applyPendingProjectCamera();
    }
    updateWindowTitle();
    const data::Grid& grid = m_overview->streamed ? m_overview->streamed->description.grid : e.grid;
    setIdle(tr("%1: %2 members of %3 on %4 x %5 x %6%7")
                .arg(QString::fromStdString(e.source))
                .arg(e.memberCount())
                .arg(QString::fromStdString(e.variable))
                .arg(grid.nx())
                .arg(grid.ny())
                .arg(grid.nz())
                .arg(m_overview->streamed
                         ? tr(", larger than the memory budget: read in slabs (see Ensemble)")
                         : QString()));
    emit ensembleLoaded();
    const session::SessionState& s = m_model->state();
    m_session->setIsovalue(*s.isovalue, s.verticalExaggeration);
}

QString MainWindow::defaultScreenshotPath(const QString& lastPath) const {
    // In the folder of the last screenshot, named after what the picture shows.
    const QString folder = lastPath.isEmpty() ? QString() : QFileInfo(lastPath).absolutePath();
    QString name = QStringLiteral("ensil.png");
    if (m_overview && m_model->state().isovalue) {
        name = QString::fromStdString(
                   engine::pictureFileStem(*m_overview->ensemble, *m_model->state().isovalue)) +
               QStringLiteral(".png");
    }
    return folder.isEmpty() ? name : QDir(folder).filePath(name);
}

void MainWindow::chooseScreenshot() {
    QSettings settings;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save Screenshot"),
        defaultScreenshotPath(settings.value(QStringLiteral("screenshot/path")).toString()),
        tr("PNG images (*.png)"));
    if (path.isEmpty()) return;
    // Any resolution: the view's own by default, or e.g. 3840x2400 for print.
    const qreal ratio = m_view->devicePixelRatioF();
    const QString viewSize = QStringLiteral("%1x%2")
                                 .arg(std::lround(m_view->width() * ratio))
                                 .arg(std::lround(m_view->height() * ratio));
    bool ok = false;
    const QString answer = QInputDialog::getText(
        this, tr("Screenshot Size"), tr("Width x height in pixels:"), QLineEdit::Normal,
        settings.value(QStringLiteral("screenshot/size"), viewSize).toString(), &ok);
    if (!ok) return;
    const QStringList parts = answer.toLower().split(QLatin1Char('x'));
    const int width = parts.size() == 2 ? parts[0].trimmed().toInt() : 0;
    const int height = parts.size() == 2 ? parts[1].trimmed().toInt() : 0;
    if (width < 16 || height < 16 || width > 16384 || height > 16384) {
        QMessageBox::warning(this, tr("Screenshot not saved"),
                             tr("'%1' is not a size such as 1920x1200 (16 to 16384 pixels a "
                                "side).")
                                 .arg(answer));
        return;
    }
    settings.setValue(QStringLiteral("screenshot/path"), path);
    settings.setValue(QStringLiteral("screenshot/size"), answer);
    QString error;
    if (!saveScreenshot(path, &error, QSize(width, height))) {
        QMessageBox::warning(this, tr("Screenshot not saved"), error);
    }
}

bool MainWindow::saveScreenshot(const QString& path, QString* error, QSize size) {
    const QImage image = size.isEmpty() ? m_view->grabFramebuffer() : m_view->renderImage(size);
    if (image.isNull()) {
        if (error != nullptr) {
            *error = tr("The view could not be drawn at %1 x %2 pixels; the graphics driver may "
                        "not allow images that large.")
                         .arg(size.width())
                         .arg(size.height());
        }
        return false;
    }
    if (!image.save(path)) {
        if (error != nullptr) *error = tr("Could not write '%1'.").arg(path);
        return false;
    }
    return true;
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
    if (!m_overview) return;
    m_view->renderer().setFloorMap(engine::sceneFloor(sceneData(), settings));
}

}  // namespace ensil::app

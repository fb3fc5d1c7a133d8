// The workbench window: the silhouette view in the centre, dock panels around it, menus with
// standard shortcuts, and the status bar that shows background work with a cancel button. It
// is a composition around one session model: every control writes into the session, and the
// bindings (main_window_session.cpp) show the session in the view and every control.
// Loading runs on a worker thread (QtConcurrent); results come back through QFutureWatcher's
// queued signals. Window layout is remembered with QSettings. GUI thread only.
#pragma once

#include <QMainWindow>
#include <QStringList>
#include <functional>
#include <memory>
#include <optional>
#include <stop_token>

#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "data/error.h"
#include "engine/ensemble_overview.h"
#include "engine/session_scene.h"
#include "engine/surface_export.h"
#include "engine/time_series.h"
#include "session/session_model.h"
#include "session/session_state.h"
#include "workbench/background_job.h"

class QProgressBar;
class QToolButton;
class QLabel;
class QMenu;
class QAction;

namespace ensil::workbench {
class IsovalueSession;
class MemberSelection;
class TimeSteps;
class Workbench;
}  // namespace ensil::workbench

namespace ensil::ui {
class SilhouetteView;
class EnsembleInfoPanel;
class RenderToolbar;
class FramePacedRepaints;
class RenderPanel;
class CuttingPlanePanel;
class AnimationBar;
class TimeBar;
class ClusterTimeline;
class OpenDataDialog;
class MemberTablePanel;
class ClusterPanel;
class DendrogramView;
class SectionsPanel;
}  // namespace ensil::ui

namespace ensil::session {
class SessionHistory;
class SessionModel;
struct ViewPreset;
}  // namespace ensil::session

namespace ensil::geo {
class MapProjection;
}  // namespace ensil::geo

namespace ensil::app {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Start loading in the background; ensembleLoaded() or loadingFailed() follows. The
    // ensemble on screen stays until the new one is ready, and stays if loading fails.
    void loadDemo(const data::DemoEnsembleParams& params = {});
    void openFiles(const data::DataSelection& selection);
    // Shows what the files hold (variables, member dimension, time index) and opens them with
    // the user's choices when the dialog is accepted. The dialog deletes itself when closed.
    ui::OpenDataDialog* chooseData(const QStringList& files);
    void cancelLoading();
    // Writes the surfaces on screen for other tools (File > Export Surfaces): the selected
    // members', else the visible ones', with the mean's and the summary surfaces, in the
    // format of the path's suffix (.vtm, .ply, .obj, .stl) and named from its base name, in
    // the background; surfacesExported() follows, or a message.
    void exportSurfaces(const QString& path);
    // The memory the workbench may take for an ensemble (`ensil --memory-limit`; by default
    // engine::defaultMemoryLimit()): data whose in-memory peak is larger are opened as a thinned
    // copy with their surfaces built from the whole data in slabs (engine/
    // workbench_reading.h), saying so. Applies to what is opened next.
    void setMemoryLimit(std::size_t bytes);
    [[nodiscard]] std::size_t memoryLimit() const;

    [[nodiscard]] ui::SilhouetteView* view() const { return m_view; }
    [[nodiscard]] ui::EnsembleInfoPanel* infoPanel() const { return m_info; }
    [[nodiscard]] ui::RenderToolbar* renderToolbar() const { return m_toolbar; }
    [[nodiscard]] ui::RenderPanel* renderPanel() const { return m_renderPanel; }
    [[nodiscard]] ui::CuttingPlanePanel* cuttingPlanePanel() const { return m_planePanel; }
    [[nodiscard]] ui::AnimationBar* animationBar() const { return m_animation; }
    [[nodiscard]] ui::TimeBar* timeBar() const { return m_timeBar; }
    [[nodiscard]] workbench::IsovalueSession* isovalueSession() const { return m_session; }
    [[nodiscard]] const engine::EnsembleOverview* overview() const;
    [[nodiscard]] bool isLoading() const;
    // The document and its controllers (workbench/workbench.h), which this window shows.
    [[nodiscard]] workbench::Workbench* workbench() const { return m_workbench; }
    // Loading or building isosurfaces.
    [[nodiscard]] bool isBusy() const;

    // The shared selection model every panel and the view follow (main_window_panels.cpp).
    [[nodiscard]] workbench::MemberSelection* memberSelection() const { return m_selection; }
    [[nodiscard]] ui::MemberTablePanel* memberTable() const { return m_memberTable; }
    [[nodiscard]] ui::ClusterPanel* clusterPanel() const { return m_clusterPanel; }
    [[nodiscard]] ui::DendrogramView* dendrogram() const { return m_dendrogram; }
    [[nodiscard]] ui::SectionsPanel* sectionsPanel() const { return m_sections; }
    // Whether a window layout was saved by an earlier run (the first run starts maximised).
    [[nodiscard]] bool hasSavedLayout() const { return m_hasSavedLayout; }
    // What `ensil [FILES | PROJECT.ensil]` (and a double-click on a file) does: shows the
    // window, with the remembered layout or maximised on the first run, and opens the demo,
    // the project or the files (main_window_project.cpp).
    void showAndOpen(const data::DataSelection& selection);

    // Saves the view (without the UI) as an image, at the view's size or any other; returns
    // false with a message on failure.
    bool saveScreenshot(const QString& path, QString* error = nullptr, QSize size = {});

    // Project files (main_window_project.cpp). Opening validates the whole file first and
    // changes nothing when it is refused; projectOpened() follows once it is applied.
    bool openProject(const QString& path);
    bool saveProjectTo(const QString& path, QString* error = nullptr);
    // The session on screen, as a project saves it.
    [[nodiscard]] session::SessionState captureSession() const;
    // Shows a session of the data on screen: settings, camera, plane, isovalue, clusters,
    // linkage and visibility (undo and redo; main_window_history.cpp).
    void applySession(const session::SessionState& state);
    // Edit > Undo and Redo, whose names say the step ("Undo Isovalue 35.6 -> 30").
    [[nodiscard]] session::SessionHistory* history() const;
    [[nodiscard]] QString projectPath() const;
    // Who is asked where a project's missing data file went (a file dialog by default);
    // an empty answer cancels opening.
    void setMissingFileLocator(std::function<QString(const QString&)> locate) {
        m_locateMissingFile = std::move(locate);
    }

public slots:
    // What the 3D view reports (ui::SilhouetteView's memberClicked, memberHovered and
    // membersBrushed): a click on a member (-1: the background; a plain click there clears),
    // the member under the pointer (-1: none), members inside a rubber band. Shift adds to the
    // selection, Ctrl toggles.
    void onMemberClicked(int member, Qt::KeyboardModifiers modifiers);
    void onMemberHovered(int member);
    void onMembersBrushed(const QList<int>& members, Qt::KeyboardModifiers modifiers);
    // Esc: stops the work in progress if there is any, otherwise clears the selection.
    void escape();

signals:
    void ensembleLoaded();
    void projectOpened();
    void loadingFailed(const QString& message);
    void surfacesExported(const QStringList& files);  // the index (.vtm) first, when there is one

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    // The floor map the rendering settings ask for (none, column maximum, mean at a level).
    void showFloor(const gl::RenderSettings& settings);
    // The field the cutting plane's cut face shows (main_window_section.cpp): given to the
    // renderer when the field, its member or its isovalue changes.
    void showSection();
    // The members' spread the context surface may be coloured by, for the data shown.
    void showSpread();
    // The data on screen and the result of the isovalue drawn, as the scene is drawn from
    // (engine/session_scene.h; main_window_section.cpp).
    [[nodiscard]] engine::SceneData sceneData() const;
    // The screenshot dialog's first suggestion: the picture's facts as a file name.
    [[nodiscard]] QString defaultScreenshotPath(const QString& lastPath) const;
    // Looks from a named view (the View menu), as a session change that undo can take back.
    void lookFrom(const session::ViewPreset& preset);
    // Time (main_window_time.cpp): the time bar and the strip, and a step that arrived shown.
    void createTimeBar();
    void showArrivedStep();
    void showProgress(double fraction);  // the status bar's progress bar, 0 to 1
    // What follows each isovalue's surfaces, in order (main_window_results.cpp).
    void showBuiltSurfaces(const QString& summary);
    void showOutlyingnessRange();  // main_window_render_docks.cpp
    void showBuiltTimeStep();      // main_window_time.cpp
    // What the window shows of the workbench's opening (main_window_loading.cpp).
    void bindOpening();
    void showOpeningFailed(const QString& message);
    void askForMemberDimension(const QString& file, const QStringList& choices);
    void createToolbar();
    void chooseFiles();
    void rememberRecent(const data::DataSelection& selection);
    void rebuildRecentMenu();
    void createMenus();
    void createDocks();
    void createRenderDocks();  // main_window_render_docks.cpp
    void restoreRenderSettings();
    void rememberRenderSettings() const;
    void createAnimation();  // main_window_animation.cpp
    [[nodiscard]] std::vector<int> animationSequence() const;
    void chooseAnimationSequence();
    [[nodiscard]] QStringList memberNames() const;
    // The plane panel's box from the renderer's display frame; updatePlaneBox also keeps the
    // plane's place across the box (written into the session).
    void setPlaneBox();
    void updatePlaneBox();
    void createStatusBar();
    // The Ensemble panel's choice of another variable of the files (main_window_variable.cpp).
    void createVariableChoice();
    void offerVariables();
    // main_window_panels.cpp
    void createPanels();
    void arrangeDefaultLayout();
    void addExportActions(QMenu* file);
    void createEditMenu();
    void linkPanels();
    void showSelectionInView();
    void chooseSurfaceExport();  // main_window_export.cpp, with the two below
    void exportDendrogram();
    void exportMemberTable();
    void showOverview();
    void setBusy(const QString& what);
    void setIdle(const QString& message);
    void createProjectActions(QMenu* file);
    void createHistory(QMenu* edit);  // main_window_history.cpp
    void bindSession();               // main_window_session.cpp
    void showSessionParts(session::SessionParts parts);
    // The view's title names this ensemble and the isovalue of the surfaces drawn, whatever is
    // being built meanwhile (gl::Renderer::setTitleOf).
    void titleTheView(const data::Ensemble& ensemble);
    // The toolbar's isovalue range: the data's values, with its units as people read them.
    void showIsovalueRange(float isovalue);
    void chooseScreenshot();
    void chooseProjectPathAndSave();
    void saveProjectReporting(const QString& path);
    QString locateMissingFileWithDialog(const QString& missing);
    // Opening a project in two steps, so that the command line can restore its layout before
    // the window is shown: reading (a refusal is reported and changes nothing), then locating
    // moved data files and loading (main_window_project.cpp).
    std::optional<session::SessionState> readProject(const QString& path);
    bool openReadProject(session::SessionState project, const QString& path);
    void applyPendingProjectCamera();
    // Width over height of the 3D view, for fitting the camera.
    [[nodiscard]] float viewAspect() const;
    void showOpenedProject(const QString& path);
    void rememberRecentProject(const QString& path);
    void rebuildRecentProjectsMenu();
    void updateWindowTitle();

    ui::SilhouetteView* m_view;
    ui::EnsembleInfoPanel* m_info = nullptr;
    QProgressBar* m_progress = nullptr;
    QToolButton* m_cancel = nullptr;
    QLabel* m_statusText = nullptr;
    QLabel* m_pointText = nullptr;  // what lies under the cursor: place, level, values
    QMenu* m_recentMenu = nullptr;
    ui::RenderToolbar* m_toolbar = nullptr;
    // While the isovalue is scrubbed, the toolbar repaints with the view's preview frames.
    ui::FramePacedRepaints* m_scrubRepaints = nullptr;
    ui::RenderPanel* m_renderPanel = nullptr;
    ui::CuttingPlanePanel* m_planePanel = nullptr;
    ui::AnimationBar* m_animation = nullptr;
    ui::TimeBar* m_timeBar = nullptr;
    ui::ClusterTimeline* m_timeline = nullptr;
    // Another time step is on its way to the screen (its first frame is a motion frame).
    bool m_stepChanging = false;
    workbench::Workbench* m_workbench;
    // The workbench's parts, named here for brevity: the session on screen (every control writes
    // into it, and its bindings show it), the shared member selection, the isovalue controller
    // and the time steps read (ahead, or visited before) and not on screen.
    session::SessionModel* const m_model;
    workbench::MemberSelection* const m_selection;
    workbench::IsovalueSession* const m_session;
    workbench::TimeSteps* const m_timeSteps;
    QList<QAction*> m_modeActions;  // keys 1 to 4
    QAction* m_planeAction = nullptr;
    bool m_showingNewData = false;  // showOverview: one rebuild at its end, not one per part
    QAction* m_resetCameraAction = nullptr;
    QList<QAction*> m_viewPresetActions;  // map view, views from the sides
    ui::MemberTablePanel* m_memberTable = nullptr;
    ui::ClusterPanel* m_clusterPanel = nullptr;
    ui::DendrogramView* m_dendrogram = nullptr;
    ui::SectionsPanel* m_sections = nullptr;
    bool m_hasSavedLayout = false;
    workbench::BackgroundJob<engine::ExportedSurfaces> m_surfaceExport{this};
    // The open grid's map projection, for the places under the cursor (none before data).
    std::unique_ptr<geo::MapProjection> m_mapProjection;
    QMenu* m_recentProjectsMenu = nullptr;
    std::function<QString(const QString&)> m_locateMissingFile;
    // What the cut face shows now, so that it is rebuilt only when that changes.
    struct ShownSection {
        gl::SectionField field = gl::SectionField::None;
        int member = -1;
        const void* exceedance = nullptr;
        const void* overview = nullptr;
        bool operator==(const ShownSection&) const = default;
    };
    ShownSection m_shownSection;
    // The member last hovered: a member section keeps showing it while the cursor moves on to
    // the section to read its values.
    int m_lastHoveredMember = -1;
};

}  // namespace ensil::app

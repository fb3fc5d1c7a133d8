// The workbench's document and its controllers, without a widget: the session model (what is on
// screen: every control writes into it), the shared member selection, the isovalue controller,
// the time steps read and kept, the data being opened (in the background, with progress and
// cancel, the data on screen kept until the new data are ready and kept when opening fails) and
// the project they belong to. The window (app/main_window.h) shows what its signals say and
// writes the user's edits into the session; the command line and Python share the engine
// beneath. Tested on a QCoreApplication (tests/workbench/workbench_test.cpp). GUI thread only.
#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <optional>

#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "engine/ensemble_overview.h"
#include "session/session_state.h"
#include "workbench/background_job.h"

namespace ensil::session {
class SessionHistory;
class SessionModel;
}  // namespace ensil::session

namespace ensil::workbench {

class IsovalueSession;
class MemberSelection;
class StepClusterStrip;
class SurfaceDisplay;
class TimeSteps;

class Workbench : public QObject {
    Q_OBJECT
public:
    // `display` (the 3D view) outlives the workbench; surfaces are cached in `cacheDirectory`.
    Workbench(SurfaceDisplay* display, const QString& cacheDirectory, QObject* parent = nullptr);
    ~Workbench() override;

    [[nodiscard]] session::SessionModel* model() const { return m_model; }
    [[nodiscard]] MemberSelection* selection() const { return m_selection; }
    [[nodiscard]] IsovalueSession* isovalue() const { return m_isovalue; }
    [[nodiscard]] TimeSteps* timeSteps() const { return m_timeSteps; }
    // Every time step's clusters (workbench/step_cluster_strip.h).
    [[nodiscard]] StepClusterStrip* strip() const { return m_strip; }
    // Undo and redo (session/session_history.h) of the session on screen.
    [[nodiscard]] session::SessionHistory* history() const { return m_history; }

    // The session as a project saves it and undo records it: the model's, the members'
    // cluster numbers, no isovalue before any surface is built, and what only the window knows
    // (the camera as it stands, the window's layout), added by `viewCapture`.
    void setViewCapture(std::function<void(session::SessionState&)> viewCapture) {
        m_viewCapture = std::move(viewCapture);
    }
    [[nodiscard]] session::SessionState captureSession() const;
    // Shows a session of the data on screen (undo, redo): the bindings show the model's parts,
    // and sessionApplied() lets the window place the camera.
    void applySession(const session::SessionState& state);

    // The data on screen (null before any), and the files they were read from with the time
    // step shown (none for the demo); while other data are opened, the files being opened.
    [[nodiscard]] const engine::EnsembleOverview* overview() const { return m_overview.get(); }
    [[nodiscard]] const std::optional<data::DataSelection>& files() const { return m_requested; }
    // The time step shown (0 for the demo, which has none).
    [[nodiscard]] std::size_t shownStep() const { return m_requested ? m_requested->timeIndex : 0; }

    // Opening data in the background: dataArrived() follows, or openingCancelled(),
    // openingFailed() or memberDimensionAsked().
    void loadDemo(const data::DemoEnsembleParams& params = {});
    void openFiles(const data::DataSelection& selection);
    [[nodiscard]] bool isOpening() const { return m_loader.isRunning(); }
    // Stops opening, a time step's reading and the surfaces being built.
    void cancel();
    // The memory an ensemble may take (`ensil --memory-limit`; 0: engine::defaultMemoryLimit()):
    // larger data are opened as a thinned copy with their surfaces built from the whole data in
    // slabs (engine/workbench_reading.h). Applies to what is opened next.
    void setMemoryLimit(std::size_t bytes) { m_memoryLimit = bytes; }
    [[nodiscard]] std::size_t memoryLimit() const;

    // The session of the data that just arrived (after dataArrived, once the window has shown
    // them): a project's being opened, else the opening isovalue (as shown, rounded to the
    // isovalue control's precision) and the default cluster count. Its surfaces are built by
    // buildFirstSurfaces, after the window has said the data are loaded.
    void startSessionOfNewData(float shownIsovalue);
    void buildFirstSurfaces();

    // Time steps (workbench_time.cpp). Another step of the files on screen: shown at once
    // when kept (read ahead, or visited before), else read in the background while the step
    // shown stays (stepReading, then stepArrived or stepFailed, which puts the session's step
    // back). An arrived step's data are on screen (the step left is kept within the memory
    // budget, its surfaces and clusters stay until the new step's are built); its surfaces are
    // built, or shown at once when built before, right after stepArrived.
    void goToStep(std::size_t step);
    // The next step in the direction of the last move (forward while playing, round the end),
    // read and its surfaces built in the background while this one is looked at, so that
    // stepping on shows it at once; a guess, dropped when the user goes elsewhere.
    void readAhead(bool playing);
    // The files on screen at another time step.
    [[nodiscard]] data::DataSelection timeStepSelection(std::size_t step) const;

    // Projects. A project whose data files were found (session::loadProject validated it):
    // its data are opened, and the project applied in two steps, its session when the data
    // arrive (startSessionOfNewData) and its members' visibility and selection once their
    // clusters are known (applyPendingProjectMembers, after the first surfaces); then
    // projectOpened(). A project whose data fail to open or whose surfaces fail is dropped.
    void openProject(session::SessionState project, const QString& path);
    [[nodiscard]] const session::SessionState* pendingProject() const {
        return m_pendingProject.get();
    }
    // What follows each isovalue's surfaces reaching the screen, after the window's part: a
    // project's members applied once their clusters are known, and new data's first surfaces
    // start the undo history afresh (what was done to the old data cannot be undone on them).
    void surfacesShown();
    // The project the session on screen was opened from or saved to (empty: none).
    [[nodiscard]] QString projectPath() const { return m_projectPath; }
    void setProjectPath(const QString& path) { m_projectPath = path; }

signals:
    void openingStarted(const QString& what);
    void progressed(double fraction);  // 0 to 1, of opening or of reading a time step
    // overview() holds the new data, which the isovalue controller, the member selection and
    // the strip have (the old data's surfaces, clusters and time steps are forgotten).
    void dataArrived();
    void openingCancelled();
    void openingFailed(const QString& message);
    // The file has no member dimension: one of `choices` may stand in for members
    // (openFiles again with DataSelection::memberDimension).
    void memberDimensionAsked(const QString& file, const QStringList& choices);
    void projectOpened(const QString& path);
    void stepReading(std::size_t step);
    void stepArrived();
    void stepFailed(const QString& message);  // empty: cancelled
    void sessionApplied(const session::SessionState& state);

private:
    // `read` on a worker, as engine::readEnsembleOverview; `identify` gives the data's
    // identity for the mesh cache.
    void startOpening(const QString& what, std::function<std::string()> identify,
                      engine::WorkbenchRead read);
    void openingEnded(const std::exception_ptr& error, bool cancelled);
    // What a worker's error says to the user.
    [[nodiscard]] static QString messageOf(const std::exception_ptr& error);
    void applyPendingProjectMembers();
    // A step's ensemble read and its overview built, on a worker; what it shares with the step
    // shown (the opening isovalue, the map lines) is taken from that one.
    [[nodiscard]] BackgroundJob<engine::EnsembleOverview>::Work readingStep(std::size_t step) const;
    void arriveAtStep(std::unique_ptr<engine::EnsembleOverview> overview, std::size_t step);
    // The step's surfaces: kept from a visit before, shown at once; else built.
    void showStepSurfaces(float isovalue, float exaggeration);
    // A step read ahead: shown if it was asked for meanwhile, else its surfaces built ahead.
    void showOrBuildStepRead(std::size_t step);
    // That step's surfaces, figures and clusters built ahead and kept by the isovalue session.
    void buildAhead(const engine::EnsembleOverview& step);

    session::SessionModel* m_model;
    MemberSelection* m_selection;
    IsovalueSession* m_isovalue;
    TimeSteps* m_timeSteps;
    StepClusterStrip* m_strip;
    session::SessionHistory* m_history;
    std::function<void(session::SessionState&)> m_viewCapture;
    bool m_historyStartsAfresh = false;  // new data: their first surfaces reset the history
    BackgroundJob<engine::EnsembleOverview> m_loader{this};
    std::unique_ptr<engine::EnsembleOverview> m_overview;
    std::optional<data::DataSelection> m_requested;  // files being opened, to retry with choices
    std::optional<data::DemoEnsembleParams> m_requestedDemo;
    std::size_t m_memoryLimit = 0;
    // A project being opened: applied when its data has loaded and its surfaces are built.
    std::unique_ptr<session::SessionState> m_pendingProject;
    QString m_pendingProjectPath;
    QString m_projectPath;
};

}  // namespace ensil::workbench

// Undo and redo in the main window: which edits are recorded as steps (every control that
// changes the session: the toolbar, the rendering and plane panels, the clusters and linkage,
// visibility, the sections' places and fill, Reset Camera), and how a step's session is shown
// again.
#include <QAction>
#include <QMenu>

#include "app/main_window.h"
#include "session/session_camera.h"
#include "session/session_history.h"
#include "widgets/cluster_panel.h"
#include "widgets/cutting_plane_panel.h"
#include "widgets/render_panel.h"
#include "widgets/render_toolbar.h"
#include "widgets/sections_panel.h"
#include "widgets/silhouette_view.h"
#include "widgets/time_bar.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"
#include "workbench/workbench.h"

namespace ensil::app {

void MainWindow::createHistory(QMenu* edit) {
    session::SessionHistory* history = m_workbench->history();
    QAction* undo = history->stack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
    QAction* redo = history->stack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redoAction"));
    redo->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    edit->addAction(undo);
    edit->addAction(redo);
    // A session is taken with the camera as it stands and the window's layout, and a step
    // undone or redone puts the camera back.
    m_workbench->setViewCapture([this](session::SessionState& s) {
        const gl::Camera& camera = m_view->renderer().camera();
        s.camera.azimuth = camera.azimuth();
        s.camera.elevation = camera.elevation();
        s.camera.placement = session::CameraState::Placement{camera.distance(), camera.target()};
        s.windowGeometry = saveGeometry();
        s.windowState = saveState();
    });
    connect(m_workbench, &workbench::Workbench::sessionApplied, this,
            [this](const session::SessionState& s) {
                session::placeCamera(s.camera, m_view->renderer());
                m_view->update();
            });

    // Recorded after the edit has reached the view (queued: every direct handler ran first).
    const auto record = [history] { history->record(); };
    const auto queued = Qt::QueuedConnection;
    connect(m_renderPanel, &ui::RenderPanel::edited, this, record, queued);
    connect(m_planePanel, &ui::CuttingPlanePanel::planeChanged, this, record, queued);
    connect(m_toolbar, &ui::RenderToolbar::isovalueChanged, this, record, queued);
    connect(m_selection, &workbench::MemberSelection::clustersChanged, this, record, queued);
    connect(m_selection, &workbench::MemberSelection::visibilityChanged, this, record, queued);
    connect(m_clusterPanel, &ui::ClusterPanel::linkageChanged, this, record, queued);
    connect(m_timeBar, &ui::TimeBar::stepRequested, this, record, queued);
    connect(m_sections, &ui::SectionsPanel::placesEdited, this, record, queued);
    connect(
        m_resetCameraAction, &QAction::triggered, this,
        [history] { history->record(/*cameraStep=*/true); }, queued);
    for (QAction* preset : m_viewPresetActions) {
        connect(
            preset, &QAction::triggered, this,
            [history, preset] {
                history->record(/*cameraStep=*/true, preset->text().remove(QLatin1Char('&')));
            },
            queued);
    }
}

session::SessionHistory* MainWindow::history() const { return m_workbench->history(); }

session::SessionState MainWindow::captureSession() const { return m_workbench->captureSession(); }

void MainWindow::applySession(const session::SessionState& s) { m_workbench->applySession(s); }

}  // namespace ensil::app

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

namespace ensil::app {

void MainWindow::createHistory(QMenu* edit) {
    m_history = new session::SessionHistory(
        [this] { return captureSession(); },
        [this](const session::SessionState& s) { applySession(s); }, this);
    QAction* undo = m_history->stack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
    QAction* redo = m_history->stack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redoAction"));
    redo->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    edit->addAction(undo);
    edit->addAction(redo);

    // Recorded after the edit has reached the view (queued: every direct handler ran first).
    const auto record = [this] { m_history->record(); };
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
        [this] { m_history->record(/*cameraStep=*/true); }, queued);
    for (QAction* preset : m_viewPresetActions) {
        connect(
            preset, &QAction::triggered, this,
            [this, preset] {
                m_history->record(/*cameraStep=*/true, preset->text().remove(QLatin1Char('&')));
            },
            queued);
    }
}

void MainWindow::applySession(const session::SessionState& s) {
    if (overview() == nullptr) return;
    m_model->replace(s);  // the bindings show it (main_window_session.cpp)
    session::placeCamera(s.camera, m_view->renderer());
    m_view->update();
}

}  // namespace ensil::app

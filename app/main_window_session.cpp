// The main window's bindings to its session model: whatever part of the session changed (an
// edit in any panel, the toolbar, the dendrogram, undo, a project, the remembered settings) is
// shown by the view, the panels, the toolbar and the shared selection, and the surfaces are
// rebuilt when the isovalue or the vertical exaggeration changed. Every control writes into
// the session (never into another control), so the window holds no second copy of it.
#include <QAction>
#include <QSignalBlocker>

#include "app/main_window.h"
#include "data/units_text.h"
#include "engine/picture_title.h"
#include "session/session_model.h"
#include "widgets/cluster_panel.h"
#include "widgets/cutting_plane_panel.h"
#include "widgets/frame_paced_repaints.h"
#include "widgets/render_panel.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"
#include "workbench/workbench.h"

namespace ensil::app {

using session::SessionPart;

void MainWindow::bindSession() {
    connect(m_model, &session::SessionModel::changed, this, &MainWindow::showSessionParts);
    // The cluster count the shared selection changes by itself (the dendrogram's cut line) goes
    // into the session too; its visibility and selection are the session's own.
    connect(m_selection, &workbench::MemberSelection::clustersChanged, this, [this] {
        if (!m_selection->isClustered()) return;
        const int k = m_selection->requestedClusterCount();
        m_model->update([k](session::SessionState& s) { s.clusters = k; });
    });
    connect(m_toolbar, &ui::RenderToolbar::isovalueChanged, this, [this](double v) {
        m_model->update([v](session::SessionState& s) { s.isovalue = static_cast<float>(v); });
    });
    // Scrubbing previews without touching the session: only the released value is a change
    // (saved, undoable); the preview is the view following the pointer.
    connect(m_toolbar, &ui::RenderToolbar::isovalueScrubbed, this, [this](double v) {
        if (overview() == nullptr) return;
        m_scrubRepaints->begin();
        m_scrubRepaints->changed();
        m_session->previewIsovalue(static_cast<float>(v), m_model->state().verticalExaggeration);
    });
    connect(m_toolbar, &ui::RenderToolbar::isovalueScrubEnded, this, [this] {
        m_scrubRepaints->end();
        m_session->endPreview();
    });
    // (The view's title names the isovalue of the surfaces drawn, the preview's too.)
    connect(m_session, &workbench::IsovalueSession::previewShown, this, [this] {
        m_scrubRepaints->frameComing();  // the toolbar's held-back repaints drawn with it
    });
    connect(m_toolbar, &ui::RenderToolbar::clusterCountChanged, this,
            [this](int k) { m_model->update([k](session::SessionState& s) { s.clusters = k; }); });
    connect(m_clusterPanel, &ui::ClusterPanel::linkageChanged, this, [this](prep::Linkage l) {
        m_model->update([l](session::SessionState& s) { s.linkage = l; });
    });
}

void MainWindow::titleTheView(const data::Ensemble& ensemble) {
    m_view->renderer().setTitleOf([words = engine::pictureTitleOf(ensemble)](float isovalue) {
        return QString::fromStdString(words(isovalue));
    });
}

void MainWindow::showIsovalueRange(float isovalue) {
    const prep::FieldStatistics& stats = overview()->statistics;
    m_toolbar->setIsovalueRange(
        stats.minimum, stats.maximum, isovalue,
        QString::fromStdString(data::readableUnits(overview()->ensemble->units)));
}

void MainWindow::showSessionParts(session::SessionParts parts) {
    gl::Renderer& renderer = m_view->renderer();
    // Another time step of the data shown (the time bar, undo): read in the background.
    if ((parts & SessionPart::Data) && overview() != nullptr && m_workbench->files() &&
        !m_showingNewData) {
        const data::DataSelection& wanted = m_model->state().data;
        if (m_workbench->timeStepSelection(wanted.timeIndex) == wanted)
            m_workbench->goToStep(wanted.timeIndex);
    }
    // First the box, which the plane is placed across: without a new plane, the plane keeps
    // its place across the reshaped box (a change of the session of its own, made here).
    if (parts & SessionPart::Exaggeration) {
        engine::showSession(renderer, m_model->state(), sceneData(), SessionPart::Exaggeration);
        if (parts & SessionPart::Plane) {
            setPlaneBox();
        } else {
            updatePlaneBox();
        }
    }
    const session::SessionState& s = m_model->state();
    // What the renderer draws of the session, as `ensil render` draws it (the data's part is
    // shown when its overview arrives, showOverview).
    engine::showSession(
        renderer, s, sceneData(),
        parts & ~session::SessionParts(SessionPart::Exaggeration | SessionPart::Data));
    if (parts & (SessionPart::Rendering | SessionPart::Plane | SessionPart::Exaggeration |
                 SessionPart::Background | SessionPart::Projection)) {
        m_renderPanel->showSession(s);
    }
    if (parts & (SessionPart::Rendering | SessionPart::Plane)) {
        m_session->setContextSurfacesWanted(s.render.drawsContextSurfaces());
        showSection();
    }
    if (parts & SessionPart::Plane) {
        m_planePanel->setPlane(s.render.plane);
        const QSignalBlocker block(m_planeAction);
        m_planeAction->setChecked(s.render.plane.enabled);
    }
    if (parts & SessionPart::Linkage) {
        m_clusterPanel->setLinkage(s.linkage);
        m_session->setLinkage(s.linkage);
    }
    if (parts & SessionPart::Clusters) m_selection->setClusterCount(s.clusters);
    if ((parts & SessionPart::Isovalue) && s.isovalue && overview() != nullptr &&
        static_cast<float>(m_toolbar->isovalue()) != *s.isovalue) {
        showIsovalueRange(*s.isovalue);
    }
    // Normals and curvatures live in display space: a new exaggeration rebuilds them (the
    // meshes come from the cache when this isovalue and exaggeration were seen before).
    if ((parts & (SessionPart::Isovalue | SessionPart::Exaggeration)) && s.isovalue &&
        overview() != nullptr && !m_showingNewData) {
        m_session->setIsovalue(*s.isovalue, s.verticalExaggeration);
    }
    // (Visibility and selection: the shared selection shows the session's, MemberSelection.)
    // Another time step alone changes nothing on screen until its surfaces are shown, which
    // draws them: a frame of the step left here took a software frame's cores (200 ms at full
    // resolution) from reading the next.
    if (parts != session::SessionParts(SessionPart::Data)) m_view->update();
}

}  // namespace ensil::app

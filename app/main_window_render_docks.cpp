// The rendering and cutting plane docks of the main window, and what keeps them in step with
// the renderer: every edit is applied to the renderer's settings and repaints the view.
#include <QAction>
#include <QDockWidget>
#include <QKeySequence>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QSignalBlocker>
#include <QSlider>

#include "app/main_window.h"
#include "data/units_text.h"
#include "preprocessing/mesh_packing.h"
#include "session/remembered_settings.h"
#include "session/session_history.h"
#include "session/session_model.h"
#include "widgets/cutting_plane_panel.h"
#include "widgets/render_panel.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/workbench.h"

namespace ensil::app {
namespace {
// Where each level of the grid's axes lies across the display box, for the plane panel.
std::array<ui::PlaneAxis, 3> planeAxes(const data::Grid& grid, const data::DisplayFrame& frame) {
    std::array<ui::PlaneAxis, 3> axes;
    const glm::vec3 centre = frame.center(), half = 0.5F * (frame.boxMax() - frame.boxMin());
    for (int a = 0; a < 3; ++a) {
        ui::PlaneAxis& axis = axes[static_cast<std::size_t>(a)];
        const data::Axis& source = grid.axis(a);
        axis.name = QString::fromStdString(source.name);
        axis.units = QString::fromStdString(source.units);
        axis.values = source.values;
        for (const double d : frame.axisTable(a)) {
            axis.positions.push_back(half[a] > 0.0F ? (d - centre[a]) / half[a] : 0.0);
        }
    }
    return axes;
}
}  // namespace

void MainWindow::createRenderDocks() {
    m_renderPanel = new ui::RenderPanel;
    m_renderPanel->showSession(m_model->state());
    auto* renderDock = new QDockWidget(tr("Rendering"), this);
    renderDock->setObjectName(QStringLiteral("renderingDock"));
    // Scrolled rather than squeezing the member table that shares the right side: the panel
    // holds more controls than a short screen has room for.
    auto* renderScroll = new QScrollArea;
    renderScroll->setWidget(m_renderPanel);
    renderScroll->setWidgetResizable(true);
    renderScroll->setFrameShape(QFrame::NoFrame);
    renderDock->setWidget(renderScroll);

    m_planePanel = new ui::CuttingPlanePanel;
    auto* planeDock = new QDockWidget(tr("Cutting Plane"), this);
    planeDock->setObjectName(QStringLiteral("cuttingPlaneDock"));
    planeDock->setWidget(m_planePanel);
    // Tabs beside the clusters: a third column of docks would squeeze the view.
    auto* clusters = findChild<QDockWidget*>(QStringLiteral("clusterDock"));
    addDockWidget(Qt::RightDockWidgetArea, renderDock);
    addDockWidget(Qt::RightDockWidgetArea, planeDock);
    if (clusters != nullptr) {
        tabifyDockWidget(clusters, renderDock);
        tabifyDockWidget(renderDock, planeDock);
        clusters->raise();
    }

    // Dragging a slider (the plane's position) redraws the view continuously, like moving the
    // camera: the view draws those frames as it draws camera motion.
    for (QSlider* slider :
         m_planePanel->findChildren<QSlider*>() + m_renderPanel->findChildren<QSlider*>()) {
        connect(slider, &QSlider::sliderPressed, m_view, &ui::SilhouetteView::beginInteraction);
        connect(slider, &QSlider::sliderReleased, m_view, &ui::SilhouetteView::endInteraction);
    }

    // Every edit goes into the session; the session's bindings show it (main_window_session.cpp).
    connect(m_renderPanel, &ui::RenderPanel::edited, this, [this] {
        m_model->update([this](session::SessionState& s) { m_renderPanel->applyTo(s); });
    });
    connect(m_planePanel, &ui::CuttingPlanePanel::planeChanged, this, [this] {
        m_model->update(
            [this](session::SessionState& s) { s.render.plane = m_planePanel->plane(); });
    });
    // Keys 1 to 4 switch the mode; Ctrl+Shift+P toggles the plane.
    const QStringList modes{tr("Shaded Silhouettes"), tr("3D Spaghetti Plot"),
                            tr("Semi-Transparent Surfaces"), tr("Opaque Surfaces")};
    for (int m = 0; m < modes.size(); ++m) {
        auto* action = new QAction(modes[m], this);
        action->setShortcut(QKeySequence(Qt::Key_1 + m));
        connect(action, &QAction::triggered, this,
                [this, m] { m_renderPanel->setMode(static_cast<gl::RenderMode>(m)); });
        m_modeActions.push_back(action);
    }
    m_planeAction = new QAction(tr("&Cutting Plane"), this);
    m_planeAction->setCheckable(true);
    m_planeAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    connect(m_planeAction, &QAction::toggled, m_planePanel, &ui::CuttingPlanePanel::setCutting);
}

void MainWindow::showOutlyingnessRange() {
    const auto& meshes = m_view->renderer().meshes();
    if (!meshes || overview() == nullptr) return;
    const QString units = QString::fromStdString(data::readableUnits(overview()->ensemble->units));
    // "K" squared is "K²", "m s⁻¹" squared is "(m s⁻¹)²".
    const QString squared = units.isEmpty() ? QString()
                            : units.contains(QRegularExpression(QStringLiteral("[ ./*-]")))
                                ? QStringLiteral("(%1)\u00b2").arg(units)
                                : units + QStringLiteral("\u00b2");
    if (m_renderPanel->setOutlyingnessRange(prep::maximumOutlyingness(*meshes), squared)) {
        // The first band the panel now shows is the one drawn (and saved, and undone).
        m_model->update([this](session::SessionState& s) { m_renderPanel->applyTo(s); });
        m_workbench->history()->absorb();
    }
}

void MainWindow::restoreRenderSettings() {
    // How the user last drew things (the remembered settings of the setting table); the cutting
    // plane and exaggeration belong to the data.
    session::SessionState state = m_model->state();
    session::restoreRemembered(QSettings(), state);
    m_model->replace(state);
}

void MainWindow::rememberRenderSettings() const {
    QSettings settings;
    session::remember(settings, captureSession());
}

void MainWindow::setPlaneBox() {
    if (overview() == nullptr) return;
    const data::DisplayFrame& frame = m_view->renderer().frame();
    m_planePanel->setBox(frame.boxMin(), frame.boxMax(),
                         planeAxes(overview()->ensemble->grid, frame));
}

void MainWindow::updatePlaneBox() {
    if (overview() == nullptr) return;
    // The plane keeps its place across the box when the box changes shape.
    const double position = m_planePanel->position();
    setPlaneBox();
    m_planePanel->setPosition(position);
    m_model->update([this](session::SessionState& s) { s.render.plane = m_planePanel->plane(); });
}

}  // namespace ensil::app

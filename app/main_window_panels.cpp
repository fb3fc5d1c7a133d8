// The main window's linked panels: the shared MemberSelection, the cluster list, member table
// and dendrogram docks, their menu entries (Edit > Clear Selection), and the
// link from the selection to the 3D view. Part of MainWindow; kept apart so main_window.cpp
// stays about loading files.
#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <algorithm>

#include "app/main_window.h"
#include "geo/map_projection.h"
#include "gl/renderer.h"
#include "widgets/cluster_panel.h"
#include "widgets/cluster_timeline.h"
#include "widgets/dendrogram_view.h"
#include "widgets/member_table_panel.h"
#include "widgets/render_toolbar.h"
#include "widgets/sections_panel.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"
#include "workbench/point_description.h"
#include "workbench/workbench.h"

namespace ensil::app {
namespace {
// Default dock sizes at first start: the view keeps most of the window.
constexpr int kSideDockWidth = 460;
constexpr int kDendrogramHeight = 230;
constexpr int kClusterListHeight = 240;
constexpr double kSectionsShare = 0.4;  // of the window's height, for the Sections dock

QDockWidget* makeDock(QMainWindow* window, const QString& title, const char* name,
                      QWidget* content) {
    auto* dock = new QDockWidget(title, window);
    dock->setObjectName(QString::fromLatin1(name));
    dock->setWidget(content);
    return dock;
}
}  // namespace

void MainWindow::createPanels() {
    m_clusterPanel = new ui::ClusterPanel(m_selection);
    m_memberTable = new ui::MemberTablePanel(m_selection);
    m_dendrogram = new ui::DendrogramView(m_selection);
    makeDock(this, tr("Clusters"), "clusterDock", m_clusterPanel);
    makeDock(this, tr("Members"), "memberTableDock", m_memberTable);
    makeDock(this, tr("Dendrogram"), "dendrogramDock", m_dendrogram);
    m_timeline = new ui::ClusterTimeline(m_selection);
    makeDock(this, tr("Clusters over Time"), "clusterTimelineDock", m_timeline);
    m_sections = new ui::SectionsPanel(m_model, m_selection);
    QDockWidget* sections = makeDock(this, tr("Sections"), "sectionsDock", m_sections);
    // The 3D view shows where the map and the cross-section lie while the dock is shown.
    connect(m_sections, &ui::SectionsPanel::guidesChanged, this, [this] {
        m_view->renderer().setSectionGuides(m_sections->guides());
        m_view->update();
    });
    // Sections are made while the user sees them (a tab behind the dendrogram is not seen,
    // though Qt keeps it visible).
    connect(sections, &QDockWidget::visibilityChanged, m_sections,
            &ui::SectionsPanel::setShownToUser);
    // Maps need more room than the dendrogram's strip: shown, the dock takes a good part of
    // the window's height (the user's own size stays once larger).
    connect(sections, &QDockWidget::visibilityChanged, this, [this, sections](bool visible) {
        if (!visible || sections->isFloating()) return;
        const int wanted = static_cast<int>(kSectionsShare * height());
        if (sections->height() < wanted) {
            resizeDocks({sections}, {wanted}, Qt::Vertical);
        }
    });
    arrangeDefaultLayout();
}

void MainWindow::arrangeDefaultLayout() {
    // One column on the right (ensemble facts and clusters as tabs above the member table) and
    // the dendrogram below the view: three docks around the view still leave it most of the
    // window. Saved layouts (restoreState) replace this.
    auto* ensemble = findChild<QDockWidget*>(QStringLiteral("ensembleDock"));
    auto* clusters = findChild<QDockWidget*>(QStringLiteral("clusterDock"));
    auto* members = findChild<QDockWidget*>(QStringLiteral("memberTableDock"));
    auto* dendrogram = findChild<QDockWidget*>(QStringLiteral("dendrogramDock"));
    auto* timeline = findChild<QDockWidget*>(QStringLiteral("clusterTimelineDock"));
    auto* sections = findChild<QDockWidget*>(QStringLiteral("sectionsDock"));
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
    addDockWidget(Qt::RightDockWidgetArea, clusters);
    splitDockWidget(clusters, members, Qt::Vertical);
    // Tabified after the split, or the split would land in the tab group.
    if (ensemble != nullptr) tabifyDockWidget(clusters, ensemble);
    addDockWidget(Qt::BottomDockWidgetArea, dendrogram);
    // Beside the dendrogram, below the view: shown for data with time steps.
    if (timeline != nullptr) splitDockWidget(dendrogram, timeline, Qt::Horizontal);
    // The sections as a tab beside the dendrogram: wide below the view, map and cross-section
    // side by side.
    if (sections != nullptr) tabifyDockWidget(dendrogram, sections);
    dendrogram->raise();
    clusters->raise();
    resizeDocks({clusters}, {kSideDockWidth}, Qt::Horizontal);
    resizeDocks({clusters, members}, {kClusterListHeight, 1000 - kClusterListHeight}, Qt::Vertical);
    resizeDocks({dendrogram}, {kDendrogramHeight}, Qt::Vertical);
}

void MainWindow::linkPanels() {
    // The selection drives the view: colours, visibility, selection and the hovered member.
    for (auto signal :
         {&workbench::MemberSelection::membersReset, &workbench::MemberSelection::clustersChanged,
          &workbench::MemberSelection::visibilityChanged,
          &workbench::MemberSelection::selectionChanged}) {
        connect(m_selection, signal, this, &MainWindow::showSelectionInView);
    }
    connect(m_selection, &workbench::MemberSelection::hoverChanged, this,
            &MainWindow::showSelectionInView);
    // The toolbar's cluster count and the dendrogram's cut line are one setting.
    connect(m_selection, &workbench::MemberSelection::clustersChanged, this, [this] {
        if (m_selection->isClustered()) {
            m_toolbar->setMemberCount(m_selection->memberCount(), m_selection->clusterCount());
        }
    });
    // The view reports picks, hovers and rubber bands here.
    connect(m_view, &ui::SilhouetteView::memberClicked, this, &MainWindow::onMemberClicked);
    connect(m_view, &ui::SilhouetteView::memberHovered, this, &MainWindow::onMemberHovered);
    connect(m_view, &ui::SilhouetteView::membersBrushed, this, &MainWindow::onMembersBrushed);
    // The place, level and values under the cursor, in the tooltip and the status bar.
    m_view->setHoverDescriber([this](const gl::PickResult& hit) {
        if (overview() == nullptr) return QString();
        const gl::Renderer& renderer = m_view->renderer();
        const workbench::PointContext context{
            overview()->ensemble.get(), &overview()->moments->mean, m_mapProjection.get(),
            &renderer.frame(), renderer.sectionShown() ? &renderer.sectionVolume() : nullptr};
        return workbench::describePoint(context, hit);
    });
    connect(m_view, &ui::SilhouetteView::hoverDescribed, m_pointText, &QLabel::setText);
}

void MainWindow::showSelectionInView() {
    gl::Renderer& renderer = m_view->renderer();
    renderer.setAppearance(m_selection->appearance());
    renderer.setHighlightedMember(m_selection->hovered());
    showSection();
    m_view->update();
}

void MainWindow::createEditMenu() {
    auto* edit = new QMenu(tr("&Edit"), this);
    // Between File and View, where people look for it.
    const QList<QAction*> menus = menuBar()->actions();
    menuBar()->insertMenu(menus.size() > 1 ? menus.at(1) : nullptr, edit);
    QAction* clear = edit->addAction(tr("&Clear Selection"), this, &MainWindow::escape);
    clear->setObjectName(QStringLiteral("clearSelectionAction"));
    clear->setShortcut(QKeySequence(Qt::Key_Escape));
    clear->setStatusTip(tr("Esc: stop the work in progress, or else clear the selection"));
    edit->addAction(tr("Select &All Members"), QKeySequence::SelectAll, this, [this] {
        QList<int> all;
        for (int m = 0; m < m_selection->memberCount(); ++m) all << m;
        m_selection->setSelection(all);
    });
    edit->addAction(tr("&Show All Members"), this, [this] { m_selection->showAll(); });
    edit->addSeparator();
    createHistory(edit);
}

bool MainWindow::isBusy() const {
    return m_workbench->isOpening() || m_surfaceExport.isRunning() ||
           (m_session != nullptr && m_session->isRunning());
}

void MainWindow::escape() {
    if (isBusy()) {
        cancelLoading();
        return;
    }
    m_selection->clearSelection();
}

void MainWindow::onMemberClicked(int member, Qt::KeyboardModifiers modifiers) {
    m_selection->click(member < 0 ? QList<int>{} : QList<int>{member}, modifiers);
}

void MainWindow::onMemberHovered(int member) { m_selection->setHovered(member); }

void MainWindow::onMembersBrushed(const QList<int>& members, Qt::KeyboardModifiers modifiers) {
    m_selection->click(members, modifiers);
}

}  // namespace ensil::app

// The animation of the main window: which members it steps through (the selected ones, or every
// visible one when none is selected, in cluster then similarity order) and showing the current
// one as a solid surface in the view.
#include <QStatusBar>

#include "app/main_window.h"
#include "preprocessing/clustering.h"
#include "widgets/animation_bar.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

namespace ensil::app {

void MainWindow::createAnimation() {
    m_animation = new ui::AnimationBar(this);
    addToolBar(Qt::TopToolBarArea, m_animation);
    connect(m_animation, &ui::AnimationBar::sequenceWanted, this,
            &MainWindow::chooseAnimationSequence);
    connect(m_animation, &ui::AnimationBar::memberShown, this, [this](int member) {
        m_view->renderer().setAnimatedMember(member);
        m_view->update();
    });
    // A new clustering changes the order: the next play computes it again (a new isovalue too:
    // showBuiltSurfaces).
    const auto forget = [this] { m_animation->setSequence({}); };
    connect(m_toolbar, &ui::RenderToolbar::clusterCountChanged, this, forget);
    connect(m_selection, &workbench::MemberSelection::selectionChanged, this, forget);
    connect(m_selection, &workbench::MemberSelection::visibilityChanged, this, forget);
    connect(m_selection, &workbench::MemberSelection::clustersChanged, this, forget);
}

std::vector<int> MainWindow::animationSequence() const {
    const workbench::IsovalueResult* result = m_session->result();
    if (result == nullptr || !m_selection->isClustered()) return {};
    const std::vector<int> order =
        prep::animationOrder(result->tree, result->distances, m_selection->clusterCount());
    const auto shown = [this](int m) { return m_selection->isMemberVisible(m); };
    bool anySelected = false;
    for (const int m : m_selection->selectedMembers()) anySelected |= shown(m);
    std::vector<int> sequence;
    for (const int m : order) {
        if (shown(m) && (m_selection->isSelected(m) || !anySelected)) sequence.push_back(m);
    }
    return sequence;
}

QStringList MainWindow::memberNames() const {
    QStringList names;
    for (int m = 0; m < m_selection->memberCount(); ++m) names.push_back(m_selection->name(m));
    return names;
}

void MainWindow::chooseAnimationSequence() {
    std::vector<int> sequence = animationSequence();
    if (sequence.empty()) {
        statusBar()->showMessage(tr("Nothing to animate yet: load an ensemble first."), 4000);
        return;
    }
    m_animation->setSequence(std::move(sequence), memberNames());
}

}  // namespace ensil::app

// What the window shows of time (workbench/workbench_time.cpp steps through it): the time bar,
// which steps the session's time index (so undo and projects know the step), the status bar
// while a step is read, the floor, section, facts and title of a step that arrived, the next
// step read ahead once a step's surfaces are on screen, and every step's clusters in the strip
// and the member table (workbench/step_cluster_strip.h).
#include <QStatusBar>
#include <utility>

#include "app/main_window.h"
#include "engine/ensemble_facts.h"
#include "engine/picture_title.h"
#include "session/session_model.h"
#include "widgets/cluster_timeline.h"
#include "widgets/ensemble_info_panel.h"
#include "widgets/member_table_model.h"
#include "widgets/member_table_panel.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "widgets/time_bar.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"
#include "workbench/step_cluster_strip.h"
#include "workbench/time_steps.h"
#include "workbench/workbench.h"

namespace ensil::app {

// A step is on screen once its surfaces are: then the bar may go on, and the next is read.
void MainWindow::showBuiltTimeStep() {
    if (overview() == nullptr || !m_workbench->files()) return;
    // Another step's surfaces: a motion frame first (a software-OpenGL frame of every member
    // at full resolution takes longer than a step may), the full one once steps pause.
    if (std::exchange(m_stepChanging, false)) m_view->showPassingChange();
    m_workbench->strip()->stepBuilt();
    m_timeBar->setShownStep(static_cast<int>(m_workbench->shownStep()));
    // The next step read ahead (and built) first: the strip's filling (started when the
    // clusters are recorded) waits for it rather than taking a worker it needs. A step
    // shown at once (built ahead, or kept) has its first frame still to draw, whose cores
    // the reading would take: then it starts after that frame, unless playing. A step built
    // here has been on screen in reduced detail; its next is read at once.
    const workbench::IsovalueResult* shown = m_session->result();
    if (m_timeBar->isPlaying() || shown == nullptr || !shown->keptInMemory) {
        m_workbench->readAhead(m_timeBar->isPlaying());
    } else {
        m_view->afterNextFrame(this, [this] { m_workbench->readAhead(m_timeBar->isPlaying()); });
    }
    m_workbench->strip()->recordShown();
}

void MainWindow::createTimeBar() {
    m_timeBar = new ui::TimeBar(this);
    addToolBar(Qt::BottomToolBarArea, m_timeBar);
    m_timeBar->hide();  // shown for data with time steps
    connect(m_timeBar, &ui::TimeBar::stepRequested, this, [this](int step) {
        m_model->update([step](session::SessionState& s) {
            s.data.timeIndex = static_cast<std::size_t>(step);
        });
    });
    connect(m_timeline, &ui::ClusterTimeline::membersClicked, m_selection,
            &workbench::MemberSelection::click);
    // Another step: read (said in the status bar), then shown with its surfaces, or the step
    // shown stays.
    connect(m_workbench, &workbench::Workbench::stepReading, this,
            [this](std::size_t step) { setBusy(tr("Reading time step %1...").arg(step + 1)); });
    connect(m_workbench, &workbench::Workbench::stepArrived, this, &MainWindow::showArrivedStep);
    connect(m_workbench, &workbench::Workbench::stepFailed, this, [this](const QString& message) {
        m_timeBar->pause();
        m_timeBar->setShownStep(static_cast<int>(m_workbench->shownStep()));
        setIdle(message.isEmpty() ? tr("Reading the time step was cancelled")
                                  : tr("Could not read the time step: %1").arg(message));
    });
    // The strip and the member table's columns per step show every step's clusters.
    workbench::StepClusterStrip* strip = m_workbench->strip();
    connect(m_timeline, &ui::ClusterTimeline::stopFillingRequested, strip,
            &workbench::StepClusterStrip::stopFilling);
    connect(strip, &workbench::StepClusterStrip::stepsChanged, this,
            [this](const QStringList& labels) {
                m_timeline->setSteps(labels);
                m_memberTable->model()->setSteps(labels);
            });
    connect(strip, &workbench::StepClusterStrip::stepClustered, this,
            [this](int step, const std::vector<int>& identities) {
                m_memberTable->model()->setStepClusters(step, identities);
                m_timeline->setStepClusters(step, identities);
            });
    connect(strip, &workbench::StepClusterStrip::currentStepChanged, this, [this](int step) {
        m_memberTable->model()->setCurrentStep(step);
        m_timeline->setCurrentStep(step);
    });
    connect(strip, &workbench::StepClusterStrip::fillingChanged, m_timeline,
            &ui::ClusterTimeline::setFilling);
}

void MainWindow::showArrivedStep() {
    m_stepChanging = true;
    const data::Ensemble& e = *overview()->ensemble;
    const session::SessionState& s = m_model->state();
    showFloor(s.render);
    m_shownSection = {};  // the field is this step's
    showSection();
    showSpread();
    m_info->showFacts(engine::ensembleFacts(*overview()));
    {
        const QSignalBlocker block(m_toolbar);
        showIsovalueRange(s.isovalue.value_or(overview()->defaultIsovalue));
        m_toolbar->setIsovalueHistogram(overview()->statistics.histogram);
    }
    titleTheView(e);
    updateWindowTitle();
}

}  // namespace ensil::app

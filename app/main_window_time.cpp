// Time as an axis of the session (issue 17). The time bar steps the session's time index (so
// undo and projects know the step); each step's ensemble is read in the background while the
// last step stays on screen, its surfaces come through the mesh cache (the time index is part
// of the data's identity), and its clusters keep their colours: the member selection matches
// each new merge tree to the last one (METHODS.md section 8), so a colour follows a group from
// step to step. While playing, the next step is read ahead; steps read are kept within a
// memory budget, so going back to one costs only its surfaces (from the cache).
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
        readAhead();
    } else {
        m_view->afterNextFrame(this, [this] { readAhead(); });
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
    connect(m_timeSteps, &workbench::TimeSteps::stepRead, this, &MainWindow::showOrBuildStepRead);
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

void MainWindow::goToTimeStep(std::size_t step) {
    if (overview() == nullptr || !m_workbench->files() || step == m_workbench->shownStep()) return;
    m_timeSteps->moved(m_workbench->shownStep(), step);
    m_workbench->strip()->pauseFilling();  // the step asked for goes first; filling resumes after
    if (std::unique_ptr<engine::EnsembleOverview> kept = m_timeSteps->take(step)) {
        showTimeStep(std::move(kept), step);
        return;
    }
    if (m_timeSteps->isReading(step)) return;  // on its way: shown when read
    setBusy(tr("Reading time step %1...").arg(step + 1));
    m_workbench->readTimeStep(
        step,
        [this, step](std::unique_ptr<engine::EnsembleOverview> read) {
            showTimeStep(std::move(read), step);
        },
        [this](const QString& message) {
            // The step shown stays; the session's step goes back to it.
            const std::size_t shown = m_workbench->shownStep();
            m_timeBar->pause();
            m_timeBar->setShownStep(static_cast<int>(shown));
            m_model->update([shown](session::SessionState& s) { s.data.timeIndex = shown; });
            setIdle(message.isEmpty() ? tr("Reading the time step was cancelled")
                                      : tr("Could not read the time step: %1").arg(message));
        });
}

void MainWindow::showTimeStep(std::unique_ptr<engine::EnsembleOverview> stepRead,
                              std::size_t step) {
    // The step left is kept (it may be visited again), within the budget; the last step's
    // surfaces, figures and clusters stay until this step's are built.
    m_workbench->showTimeStep(std::move(stepRead), step);
    m_stepChanging = true;
    const data::Ensemble& e = *overview()->ensemble;
    const session::SessionState& s = m_model->state();
    showFloor(s.render);
    m_shownSection = {};  // the field is this step's
    showSection();
    showSpread();
    m_info->showFacts(engine::ensembleFacts(*overview()));
    const float isovalue = s.isovalue.value_or(overview()->defaultIsovalue);
    const prep::FieldStatistics& stats = overview()->statistics;
    {
        const QSignalBlocker block(m_toolbar);
        showIsovalueRange(isovalue);
        m_toolbar->setIsovalueHistogram(stats.histogram);
    }
    titleTheView(e);
    updateWindowTitle();
    showStepSurfaces(isovalue, s.verticalExaggeration);
}

void MainWindow::showStepSurfaces(float isovalue, float exaggeration) {
    // Kept from a visit before: shown at once, in this event, so the step's surfaces, clusters
    // and panels come together with its floor and title, with no frame of the last step in
    // between and no wait for a worker (a job runs at low priority and may wait for a core
    // while the window draws). Otherwise built (or taken from the mesh cache) by a job.
    if (m_session->showKept(isovalue, exaggeration)) return;
    m_session->setIsovalue(isovalue, exaggeration);
    // A step never seen is on screen sooner in reduced detail (not one built ahead, nearly
    // done, whose cores the preview would take).
    m_session->previewTimeStep(isovalue, exaggeration);
}

void MainWindow::readAhead() {
    if (!m_workbench->files() || overview() == nullptr) return;
    const std::optional<std::size_t> next = m_timeSteps->nextToRead(
        m_workbench->shownStep(), static_cast<std::size_t>(std::max(0, m_timeBar->stepCount())),
        m_timeBar->isPlaying());
    if (!next || m_timeSteps->isReading(*next)) return;
    if (const engine::EnsembleOverview* kept = m_timeSteps->kept(*next)) {
        buildAhead(*kept);
        return;
    }
    m_timeSteps->readAhead(*next, m_workbench->readingStep(*next));
}

void MainWindow::showOrBuildStepRead(std::size_t step) {
    // Asked for while it was being read: shown now.
    if (m_model->state().data.timeIndex == step && m_workbench->files() &&
        m_workbench->shownStep() != step) {
        showTimeStep(m_timeSteps->take(step), step);
        return;
    }
    if (const engine::EnsembleOverview* read = m_timeSteps->kept(step)) buildAhead(*read);
    m_workbench->strip()->fill();
}

void MainWindow::buildAhead(const engine::EnsembleOverview& step) {
    // Data larger than memory would be read whole again in slabs for a guess: not built ahead.
    if (step.streamed) return;
    const session::SessionState& s = m_model->state();
    m_session->prepareTimeStep(step.ensemble, step.moments, step.sourceKey,
                               s.isovalue.value_or(step.defaultIsovalue), s.verticalExaggeration);
}

}  // namespace ensil::app

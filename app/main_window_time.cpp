// Time as an axis of the session (issue 17). The time bar steps the session's time index (so
// undo and projects know the step); each step's ensemble is read in the background while the
// last step stays on screen, its surfaces come through the mesh cache (the time index is part
// of the data's identity), and its clusters keep their colours: the member selection matches
// each new merge tree to the last one (METHODS.md section 8), so a colour follows a group from
// step to step. While playing, the next step is read ahead; steps read are kept within a
// memory budget, so going back to one costs only its surfaces (from the cache).
#include <QStatusBar>
#include <algorithm>

#include "app/ensemble_facts.h"
#include "app/headless/picture_title.h"
#include "widgets/ensemble_info_panel.h"
#include "app/isovalue_session.h"
#include "app/main_window.h"
#include "widgets/cluster_timeline.h"
#include "widgets/member_selection.h"
#include "widgets/render_toolbar.h"
#include "widgets/session/session_model.h"
#include "widgets/silhouette_view.h"
#include "widgets/time_bar.h"

namespace ensil::app {
namespace {

// The ensembles of the steps kept besides the one shown: a quarter of the memory available now,
// at most 2 GiB, and always the next step (reading ahead is what makes playing smooth).
std::size_t timeStepBudget() {
    constexpr std::size_t kMost = std::size_t{2} << 30;
    return std::min(kMost, data::availableMemoryBytes() / 4);
}

}  // namespace

BackgroundJob<EnsembleOverview>::Work MainWindow::readingStep(
    const data::DataSelection& selection) {
    return [selection](const std::stop_token& stop, const data::Progress& progress) {
        return loadOverview(
            [selection](const std::stop_token& s, const data::Progress& p) {
                return data::openEnsemble(selection, s, p);
            },
            [selection] { return data::sourceIdentity(selection); }, stop, progress);
    };
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
    // A step is on screen once its surfaces are: then the bar may go on, and the next is read.
    connect(m_session, &IsovalueSession::finished, this, [this] {
        if (!m_overview || !m_requested) return;
        m_timeBar->setShownStep(static_cast<int>(m_requested->timeIndex));
        recordStepClusters();
        if (m_timeBar->isPlaying()) readAhead();
    });
    connect(m_selection, &ui::MemberSelection::clustersChanged, this,
            &MainWindow::recordStepClusters);
    connect(m_timeline, &ui::ClusterTimeline::membersClicked, m_selection,
            &ui::MemberSelection::click);
}

void MainWindow::recordStepClusters() {
    if (!m_overview || !m_requested || !m_selection->isClustered() ||
        m_session->isRunning()) {
        return;
    }
    // Steps recorded at another cluster count are not comparable: they are built again as
    // they are visited.
    if (m_selection->clusterCount() != m_timelineClusters) {
        QStringList labels;
        for (const std::string& l : m_overview->ensemble->timeSteps.labels) {
            labels << QString::fromStdString(l);
        }
        m_timeline->setSteps(labels);
        m_timelineClusters = m_selection->clusterCount();
    }
    std::vector<int> identities(static_cast<std::size_t>(m_selection->memberCount()));
    for (int m = 0; m < m_selection->memberCount(); ++m) {
        identities[static_cast<std::size_t>(m)] = m_selection->identityOf(m_selection->clusterOf(m));
    }
    const int step = static_cast<int>(m_requested->timeIndex);
    m_timeline->setStepClusters(step, std::move(identities));
    m_timeline->setCurrentStep(step);
}

data::DataSelection MainWindow::timeStepSelection(std::size_t step) const {
    data::DataSelection selection = m_requested.value_or(data::DataSelection{});
    selection.timeIndex = step;
    return selection;
}

void MainWindow::goToTimeStep(std::size_t step) {
    if (!m_overview || !m_requested || step == m_requested->timeIndex) return;
    if (const auto kept = m_timeSteps.find(step); kept != m_timeSteps.end()) {
        std::unique_ptr<EnsembleOverview> overview = std::move(kept->second);
        m_timeSteps.erase(kept);
        showTimeStep(std::move(overview), step);
        return;
    }
    if (m_readAhead.isRunning() && m_readingAhead == step) return;  // on its way: shown when read
    setBusy(tr("Reading time step %1...").arg(step + 1));
    const data::DataSelection selection = timeStepSelection(step);
    m_loader.start(
        readingStep(selection),
        [this, step](EnsembleOverview overview) {
            showTimeStep(std::make_unique<EnsembleOverview>(std::move(overview)), step);
        },
        [this](const std::exception_ptr& error, bool cancelled) {
            // The step shown stays; the session's step goes back to it.
            const std::size_t shown = m_requested ? m_requested->timeIndex : 0;
            m_timeBar->pause();
            m_timeBar->setShownStep(static_cast<int>(shown));
            m_model->update([shown](session::SessionState& s) { s.data.timeIndex = shown; });
            if (cancelled || !error) {
                setIdle(tr("Reading the time step was cancelled"));
                return;
            }
            try {
                std::rethrow_exception(error);
            } catch (const std::exception& e) {
                setIdle(tr("Could not read the time step: %1").arg(QString::fromUtf8(e.what())));
            }
        },
        [this](double f) { showProgress(f); });
}

void MainWindow::showTimeStep(std::unique_ptr<EnsembleOverview> overview, std::size_t step) {
    // The step left is kept (it may be visited again), within the budget.
    const std::size_t left = m_requested->timeIndex;
    m_timeSteps[left] = std::move(m_overview);
    m_overview = std::move(overview);
    m_requested->timeIndex = step;
    std::size_t bytes = 0;
    for (const auto& [index, kept] : m_timeSteps) bytes += kept->ensemble->bytes();
    // The steps farthest from the one shown go first.
    while (bytes > timeStepBudget() && m_timeSteps.size() > 1) {
        auto farthest = std::max_element(m_timeSteps.begin(), m_timeSteps.end(),
                                         [step](const auto& a, const auto& b) {
                                             const auto distance = [step](std::size_t s) {
                                                 return s > step ? s - step : step - s;
                                             };
                                             return distance(a.first) < distance(b.first);
                                         });
        bytes -= farthest->second->ensemble->bytes();
        m_timeSteps.erase(farthest);
    }
    const data::Ensemble& e = *m_overview->ensemble;
    const session::SessionState& s = m_model->state();
    showFloor(s.render);
    m_shownSection = {};  // the field is this step's
    showSection();
    showSpread();
    m_info->showFacts(ensembleFacts(*m_overview));
    // The last step's surfaces, figures and clusters stay until this step's are built.
    m_session->setTimeStep(m_overview->ensemble, m_overview->moments, m_overview->sourceKey);
    const float isovalue = s.isovalue.value_or(m_overview->defaultIsovalue);
    const prep::FieldStatistics& stats = m_overview->statistics;
    {
        const QSignalBlocker block(m_toolbar);
        m_toolbar->setIsovalueRange(stats.minimum, stats.maximum, isovalue,
                                    QString::fromStdString(e.units));
        m_toolbar->setIsovalueHistogram(stats.histogram);
    }
    m_view->renderer().setTitle(QString::fromStdString(pictureTitle(e, isovalue)));
    updateWindowTitle();
    m_session->setIsovalue(isovalue, s.verticalExaggeration);
}

void MainWindow::readAhead() {
    if (!m_requested || m_timeBar->stepCount() < 2) return;
    const auto n = static_cast<std::size_t>(m_timeBar->stepCount());
    const std::size_t next = (m_requested->timeIndex + 1) % n;
    if (m_timeSteps.count(next) != 0 || (m_readAhead.isRunning() && m_readingAhead == next)) {
        return;
    }
    m_readingAhead = next;
    const data::DataSelection selection = timeStepSelection(next);
    m_readAhead.start(
        readingStep(selection),
        [this, next](EnsembleOverview overview) {
            auto read = std::make_unique<EnsembleOverview>(std::move(overview));
            // Asked for while it was being read: shown now.
            if (m_model->state().data.timeIndex == next && m_requested &&
                m_requested->timeIndex != next) {
                showTimeStep(std::move(read), next);
                return;
            }
            m_timeSteps[next] = std::move(read);
        },
        // Reading ahead is a guess: a failure is said when the step is asked for.
        [](const std::exception_ptr&, bool) {});
}

void MainWindow::forgetTimeSteps() {
    m_readAhead.cancel();
    m_timeSteps.clear();
}

}  // namespace ensil::app

// Time as an axis of the workbench's session (part of Workbench; issue 17). The session's time
// index says which step is shown (so undo and projects know it); each step's ensemble is read in
// the background while the last step stays on screen, its surfaces come through the mesh cache
// (the time index is part of the data's identity), and its clusters keep their colours (the
// member selection matches each new merge tree to the last one, METHODS.md section 8). The
// next step is read ahead; steps read are kept within a memory budget (TimeSteps), so going
// back to one costs only its surfaces, or nothing when they were kept too.
#include <utility>

#include "engine/ensemble_overview.h"
#include "engine/workbench_reading.h"
#include "session/session_model.h"
#include "workbench/isovalue_session.h"
#include "workbench/step_cluster_strip.h"
#include "workbench/time_steps.h"
#include "workbench/workbench.h"

namespace ensil::workbench {

data::DataSelection Workbench::timeStepSelection(std::size_t step) const {
    data::DataSelection selection = m_requested.value_or(data::DataSelection{});
    selection.timeIndex = step;
    return selection;
}

BackgroundJob<engine::EnsembleOverview>::Work Workbench::readingStep(std::size_t step) const {
    return [selection = timeStepSelection(step), memoryLimit = memoryLimit(),
            sameData = engine::sameDataParts(*m_overview)](const std::stop_token& stop,
                                                           const data::Progress& progress) {
        return engine::readEnsembleOverview(
            [selection, memoryLimit](const std::stop_token& s, const data::Progress& p) {
                return engine::readForWorkbench(selection, memoryLimit, s, p);
            },
            [selection] { return data::sourceIdentity(selection); }, stop, progress, &sameData);
    };
}

void Workbench::goToStep(std::size_t step) {
    if (!m_overview || !m_requested || step == m_requested->timeIndex) return;
    m_timeSteps->moved(m_requested->timeIndex, step);
    m_strip->pauseFilling();  // the step asked for goes first; filling resumes after
    if (std::unique_ptr<engine::EnsembleOverview> kept = m_timeSteps->take(step)) {
        arriveAtStep(std::move(kept), step);
        return;
    }
    if (m_timeSteps->isReading(step)) return;  // on its way: shown when read
    emit stepReading(step);
    m_loader.start(
        readingStep(step),
        [this, step](engine::EnsembleOverview overview) {
            if (shownStep() == step) return;  // shown meanwhile
            arriveAtStep(std::make_unique<engine::EnsembleOverview>(std::move(overview)), step);
        },
        [this](const std::exception_ptr& error, bool cancelled) {
            // The step shown stays; the session's step goes back to it.
            const std::size_t shown = shownStep();
            m_model->update([shown](session::SessionState& s) { s.data.timeIndex = shown; });
            emit stepFailed(cancelled || !error ? QString() : messageOf(error));
        },
        [this](double f) { emit progressed(f); });
}

void Workbench::arriveAtStep(std::unique_ptr<engine::EnsembleOverview> overview, std::size_t step) {
    // The step left is kept (it may be visited again), within the budget.
    m_timeSteps->keep(m_requested->timeIndex, std::move(m_overview), step);
    m_overview = std::move(overview);
    m_requested->timeIndex = step;
    m_strip->stepChanging();  // until this step's surfaces and clusters are built
    // The last step's surfaces, figures and clusters stay until this step's are built.
    m_isovalue->setTimeStep(m_overview->ensemble, m_overview->moments, m_overview->sourceKey,
                            m_overview->streamed);
    emit stepArrived();
    const session::SessionState& s = m_model->state();
    showStepSurfaces(s.isovalue.value_or(m_overview->defaultIsovalue), s.verticalExaggeration);
}

void Workbench::showStepSurfaces(float isovalue, float exaggeration) {
    // Kept from a visit before: shown at once, in this event, so the step's surfaces, clusters
    // and panels come together with its floor and title, with no frame of the last step in
    // between and no wait for a worker (a job runs at low priority and may wait for a core
    // while the window draws). Otherwise built (or taken from the mesh cache) by a job.
    if (m_isovalue->showKept(isovalue, exaggeration)) return;
    m_isovalue->setIsovalue(isovalue, exaggeration);
    // A step never seen is on screen sooner in reduced detail (not one built ahead, nearly
    // done, whose cores the preview would take).
    m_isovalue->previewTimeStep(isovalue, exaggeration);
}

void Workbench::readAhead(bool playing) {
    if (!m_requested || !m_overview) return;
    const std::optional<std::size_t> next = m_timeSteps->nextToRead(
        m_requested->timeIndex, static_cast<std::size_t>(m_strip->stepCount()), playing);
    if (!next || m_timeSteps->isReading(*next)) return;
    if (const engine::EnsembleOverview* kept = m_timeSteps->kept(*next)) {
        buildAhead(*kept);
        return;
    }
    m_timeSteps->readAhead(*next, readingStep(*next));
}

void Workbench::showOrBuildStepRead(std::size_t step) {
    // Asked for while it was being read: shown now.
    if (m_model->state().data.timeIndex == step && m_requested && shownStep() != step) {
        arriveAtStep(m_timeSteps->take(step), step);
        return;
    }
    if (const engine::EnsembleOverview* read = m_timeSteps->kept(step)) buildAhead(*read);
    m_strip->fill();
}

void Workbench::buildAhead(const engine::EnsembleOverview& step) {
    // Data larger than memory would be read whole again in slabs for a guess: not built ahead.
    if (step.streamed) return;
    const session::SessionState& s = m_model->state();
    m_isovalue->prepareTimeStep(step.ensemble, step.moments, step.sourceKey,
                                s.isovalue.value_or(step.defaultIsovalue), s.verticalExaggeration);
}

}  // namespace ensil::workbench

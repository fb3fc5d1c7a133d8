#include "workbench/step_cluster_strip.h"

#include <QTimer>
#include <optional>
#include <string>
#include <utility>

#include "session/session_model.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"
#include "workbench/time_steps.h"
#include "workbench/workbench.h"

namespace ensil::workbench {
namespace {

// The members shown, by name: the steps' clusters are matched to them by name.
std::vector<std::string> namesOf(const MemberSelection& selection) {
    std::vector<std::string> names;
    names.reserve(static_cast<std::size_t>(selection.memberCount()));
    for (int m = 0; m < selection.memberCount(); ++m)
        names.push_back(selection.name(m).toStdString());
    return names;
}

}  // namespace

StepClusterStrip::StepClusterStrip(Workbench* workbench)
    : QObject(workbench), m_workbench(workbench) {}

void StepClusterStrip::setSteps(const QStringList& labels) {
    m_fill.cancel();  // clustered as the strip was
    m_labels = labels;
    m_steps.assign(static_cast<std::size_t>(labels.size()), {});
    m_key.clear();
    emit stepsChanged(labels);
    emit fillingChanged(0, 0);
}

const std::vector<int>& StepClusterStrip::stepClusters(int step) const {
    static const std::vector<int> none;
    return step >= 0 && step < stepCount() ? m_steps[static_cast<std::size_t>(step)] : none;
}

void StepClusterStrip::forget() {
    m_clusteredStep = -1;
    m_fill.cancel();
    m_stopped = false;
}

void StepClusterStrip::stepBuilt() { m_clusteredStep = static_cast<int>(m_workbench->shownStep()); }

QString StepClusterStrip::clusteringKey() const {
    const engine::EnsembleOverview* overview = m_workbench->overview();
    const float isovalue =
        m_workbench->model()->state().isovalue.value_or(overview->defaultIsovalue);
    return QStringLiteral("%1 clusters at %2, linkage %3")
        .arg(m_workbench->selection()->clusterCount())
        .arg(static_cast<double>(isovalue), 0, 'g', 9)
        .arg(static_cast<int>(m_workbench->isovalue()->linkage()));
}

void StepClusterStrip::recordShown() {
    const MemberSelection& selection = *m_workbench->selection();
    // Only the clusters of the step they belong to: while a step is built, the last step's
    // are still shown (and may change, a new k).
    if (m_workbench->overview() == nullptr || !m_workbench->files() || !selection.isClustered() ||
        m_workbench->isovalue()->isRunning() ||
        m_clusteredStep != static_cast<int>(m_workbench->shownStep())) {
        return;
    }
    // Steps clustered at another cluster count, isovalue or linkage are not comparable: they
    // are clustered again.
    if (const QString key = clusteringKey(); key != m_key) {
        setSteps(m_labels);
        m_key = key;
    }
    std::vector<int> identities(static_cast<std::size_t>(selection.memberCount()));
    for (int m = 0; m < selection.memberCount(); ++m) {
        identities[static_cast<std::size_t>(m)] = selection.identityOf(selection.clusterOf(m));
    }
    const int step = m_clusteredStep;
    if (step >= stepCount()) return;
    m_steps[static_cast<std::size_t>(step)] = identities;
    emit stepClustered(step, identities);
    emit currentStepChanged(step);
    fill();
}

void StepClusterStrip::stopFilling() {
    m_stopped = true;
    m_fill.cancel();
    emit fillingChanged(0, 0);
}

void StepClusterStrip::fill() {
    const int n = stepCount();
    const engine::EnsembleOverview* overview = m_workbench->overview();
    if (overview == nullptr || !m_workbench->files() || n < 2 || m_stopped || m_key.isEmpty()) {
        emit fillingChanged(0, 0);
        return;
    }
    // What the user asked for goes first: the next step waits while one is read or built
    // (and one under way is cancelled when a step is asked for, pauseFilling).
    const IsovalueSession& isovalue = *m_workbench->isovalue();
    if (m_fill.isRunning() || m_workbench->isOpening() ||
        m_workbench->timeSteps()->isReadingAny() || isovalue.isRunning() ||
        isovalue.isPreparing()) {
        return;
    }
    const auto clustered = [this](int s) { return !stepClusters(s).empty(); };
    int done = 0;
    for (int s = 0; s < n; ++s) done += clustered(s) ? 1 : 0;
    emit fillingChanged(done, n);
    const std::optional<StepToCluster> next =
        nextStepToCluster(static_cast<int>(m_workbench->shownStep()), n, clustered);
    if (!next) return;
    const int step = next->step;
    const MemberSelection& selection = *m_workbench->selection();
    engine::StepClusteringRequest request;
    request.selection = m_workbench->timeStepSelection(static_cast<std::size_t>(step));
    request.isovalue = m_workbench->model()->state().isovalue.value_or(overview->defaultIsovalue);
    request.k = selection.clusterCount();
    request.linkage = isovalue.linkage();
    request.previousMembers = namesOf(selection);
    request.previousIdentities = stepClusters(next->neighbour);
    if (overview->streamed) request.memoryLimit = overview->streamed->memoryLimit;
    m_fill.start(
        [request](const std::stop_token& stop, const data::Progress& progress) {
            return engine::clusterTimeStep(request, stop, progress);
        },
        [this, step, key = m_key](const engine::StepClusters& clusters) {
            if (key == m_key && step < stepCount()) {
                // Onto the members shown (a member without data there has none).
                std::vector<int> identities =
                    engine::previousIdentitiesByName(clusters.members, clusters.memberIdentities,
                                                     namesOf(*m_workbench->selection()));
                m_steps[static_cast<std::size_t>(step)] = identities;
                emit stepClustered(step, identities);
            }
            QTimer::singleShot(0, this, &StepClusterStrip::fill);  // after the events waiting
        },
        [this](const std::exception_ptr& error, bool cancelled) {
            if (error && !cancelled) {
                // A step that cannot be read is said when it is visited; the strip stays as is.
                m_stopped = true;
                emit fillingChanged(0, 0);
                return;
            }
            QTimer::singleShot(0, this, &StepClusterStrip::fill);  // after the events waiting
        });
}

}  // namespace ensil::workbench

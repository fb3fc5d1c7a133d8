// The clusters of every time step, for the "Clusters over Time" strip and the member table's
// column per step: the step shown gives its clusters once its surfaces are built (recordShown),
// and the steps not visited are clustered in the background one at a time (reading the step, its
// distances and clusters; no surfaces), nearest to the step shown first, each matched to its
// neighbour's identities so that a colour follows a group (METHODS.md section 8). Filling waits
// while a step the user asked for is read or built, is stopped on request until other data are
// opened, and starts again from nothing when the steps are clustered otherwise (another cluster
// count, isovalue or linkage: not comparable). Widget-free; the window shows what it says. GUI
// thread only.
#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <vector>

#include "engine/time_series.h"
#include "workbench/background_job.h"

namespace ensil::workbench {

class Workbench;

class StepClusterStrip : public QObject {
    Q_OBJECT
public:
    // The workbench outlives the strip (it owns it).
    explicit StepClusterStrip(Workbench* workbench);

    // New steps (new data, or steps clustered otherwise): every step's clusters forgotten.
    void setSteps(const QStringList& labels);
    [[nodiscard]] int stepCount() const { return static_cast<int>(m_steps.size()); }
    [[nodiscard]] const QStringList& labels() const { return m_labels; }
    // A step's cluster identity per member shown (empty: not clustered yet).
    [[nodiscard]] const std::vector<int>& stepClusters(int step) const;
    // Other data: their clusters come with their first surfaces, and the strip fills again.
    void forget();
    // Another step is on its way to the screen: the clusters shown are the last step's until
    // its surfaces are built (stepBuilt).
    void stepChanging() { m_clusteredStep = -1; }
    void stepBuilt();
    // The clusters of the step on screen, once they are that step's; then filling goes on.
    void recordShown();
    // Clusters the next step not clustered, unless something the user asked for is under way.
    void fill();
    // The user asked for a step: it goes first (filling resumes after).
    void pauseFilling() { m_fill.cancel(); }
    // The strip's stop button: no more filling until other data are opened.
    void stopFilling();

signals:
    void stepsChanged(const QStringList& labels);
    void stepClustered(int step, const std::vector<int>& identities);
    void currentStepChanged(int step);
    // `done` of `total` steps clustered while filling goes on; (0, 0) when it does not.
    void fillingChanged(int done, int total);

private:
    // The clusters, isovalue and linkage the steps were clustered at.
    [[nodiscard]] QString clusteringKey() const;

    Workbench* m_workbench;
    QStringList m_labels;
    std::vector<std::vector<int>> m_steps;
    QString m_key;
    // The time step whose clusters the selection shows: -1 from a step's request until its
    // surfaces are built (the last step's clusters stay on screen meanwhile).
    int m_clusteredStep = -1;
    bool m_stopped = false;
    BackgroundJob<engine::StepClusters> m_fill{this};
};

}  // namespace ensil::workbench

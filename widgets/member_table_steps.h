// The member table's optional columns of clusters over time (issue 17): one column per time
// step, each cell the member's cluster at that step as the clusters-over-time strip shows it
// (its stable number and colour), empty for a step not clustered yet. A member that changed
// group since the previous clustered step is set in bold, so who moves reads down a column.
// Plain data behind MemberTableModel, which owns one; GUI thread.
#pragma once

#include <QColor>
#include <QFont>
#include <QString>
#include <QStringList>
#include <QVariant>
#include <vector>

namespace ensil::ui {

class MemberTableSteps {
public:
    // The steps' labels (dates); forgets every step's clusters.
    void setSteps(QStringList labels);
    // A step's clusters: each member's cluster identity (-1: none). False for a step out of
    // range.
    bool setStepClusters(int step, std::vector<int> identities);
    void setCurrentStep(int step) { m_current = step; }

    [[nodiscard]] int stepCount() const { return static_cast<int>(m_labels.size()); }
    [[nodiscard]] int currentStep() const { return m_current; }
    // The member's identity at a step; -1 when the step is not clustered or it has none.
    [[nodiscard]] int identityAt(int step, int member) const;
    // Whether the member is in another cluster than at the closest earlier clustered step.
    [[nodiscard]] bool movedAt(int step, int member) const;

    // A cell's data for Qt's roles (display: the cluster's number; decoration: its colour;
    // font: bold when the member moved; tooltip), and the header's.
    [[nodiscard]] QVariant data(int step, int member, const QString& memberName, int role,
                                int sortRole) const;
    [[nodiscard]] QVariant headerData(int step, int role) const;

private:
    [[nodiscard]] QString shortLabel(int step) const;

    QStringList m_labels;
    std::vector<std::vector<int>> m_identities;  // per step, per member; empty: not clustered
    int m_current = -1;
};

}  // namespace ensil::ui

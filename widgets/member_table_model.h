// The members as a table for QTableView: index, name, cluster (with its colour), distance to
// the mean member, mean outlyingness, inclusion depth (the contour boxplot's median and outliers
// named in its cell: "0.672 · median"), and a visibility checkbox; the hovered member's row is
// tinted. A view onto workbench::MemberSelection, which it follows and edits (the checkbox);
// selection is not part of the model but of the shared workbench::MemberSelection (see
// MemberTablePanel). For data with time steps, optional columns after these give each member's
// cluster at each step (MemberTableSteps). GUI thread only.
#pragma once

#include <QAbstractTableModel>
#include <vector>

#include "widgets/member_table_steps.h"

namespace ensil::workbench {
class MemberSelection;
}  // namespace ensil::workbench

namespace ensil::ui {

class MemberTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Index,
        Name,
        Cluster,
        DistanceToMean,
        MeanOutlyingness,
        Depth,
        Visible,
        ColumnCount
    };
    // Numbers for sorting (Qt::DisplayRole holds the text shown).
    static constexpr int SortRole = Qt::UserRole + 1;

    explicit MemberTableModel(workbench::MemberSelection* selection, QObject* parent = nullptr);

    [[nodiscard]] int rowCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex& index, int role) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation,
                                      int role) const override;
    [[nodiscard]] Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

    // Clusters over time: the steps (new data; forgets their clusters), a step's clusters
    // (each member's cluster identity, -1 for none), the step on screen (its header in bold),
    // and whether the columns of the steps are shown (one per step, after ColumnCount).
    void setSteps(const QStringList& labels);
    void setStepClusters(int step, std::vector<int> identities);
    void setCurrentStep(int step);
    void setStepColumnsShown(bool shown);
    [[nodiscard]] bool stepColumnsShown() const { return m_stepColumnsShown; }
    [[nodiscard]] int stepCount() const { return m_steps.stepCount(); }
    // The column of a time step's clusters (while they are shown).
    [[nodiscard]] static int stepColumn(int step) { return ColumnCount + step; }

signals:
    void stepsChanged(int count);

private:
    void columnChanged(int column, const QList<int>& roles);
    void rowChanged(int row, const QList<int>& roles);
    [[nodiscard]] QString depthToolTip(int member) const;

    workbench::MemberSelection* m_selection;
    MemberTableSteps m_steps;
    bool m_stepColumnsShown = false;
    int m_hoveredRow = -1;  // the row tinted as hovered, to clear it when the hover moves
};

}  // namespace ensil::ui

// The clusters of the current cut as a list for QTableView/QTreeView: the cluster's colour
// swatch and name, its size, what it holds of the contour boxplot (the median, outliers), and
// a visibility checkbox (checked when all its members are visible, partly when some are). A view
// onto workbench::MemberSelection, which it follows and edits (the checkbox). GUI thread only.
#pragma once

#include <QAbstractTableModel>

namespace ensil::workbench {
class MemberSelection;
}  // namespace ensil::workbench

namespace ensil::ui {

class ClusterListModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Cluster, Size, Boxplot, Visible, ColumnCount };

    explicit ClusterListModel(workbench::MemberSelection* selection, QObject* parent = nullptr);

    [[nodiscard]] int rowCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex& index, int role) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation,
                                      int role) const override;
    [[nodiscard]] Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

private:
    workbench::MemberSelection* m_selection;
};

}  // namespace ensil::ui

// The members as a table for QTableView: index, name, cluster (with its colour), distance to
// the mean member, mean outlyingness, inclusion depth (the contour boxplot's median and outliers
// named in its cell: "0.672 · median"), and a visibility checkbox; the hovered member's row is
// tinted. A view onto MemberSelection, which it follows and edits (the checkbox); selection is
// not part of the model but of the shared MemberSelection (see MemberTablePanel). GUI thread
// only.
#pragma once

#include <QAbstractTableModel>

namespace ensil::ui {

class MemberSelection;

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

    explicit MemberTableModel(MemberSelection* selection, QObject* parent = nullptr);

    [[nodiscard]] int rowCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex& index, int role) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation,
                                      int role) const override;
    [[nodiscard]] Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

private:
    void columnChanged(int column, const QList<int>& roles);
    void rowChanged(int row, const QList<int>& roles);
    [[nodiscard]] QString depthToolTip(int member) const;

    MemberSelection* m_selection;
    int m_hoveredRow = -1;  // the row tinted as hovered, to clear it when the hover moves
};

}  // namespace ensil::ui

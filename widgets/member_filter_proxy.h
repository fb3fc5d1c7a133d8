// Sorting and filtering for the member table. Sorts by MemberTableModel::SortRole, so numbers
// sort as numbers and unknown values (NaN) come after
// every number when ascending. The filter text keeps
// the members whose name contains it (ignoring case) or whose table index (#) it is.
// GUI thread only.
#pragma once

#include <QSortFilterProxyModel>

namespace ensil::ui {

class MemberFilterProxy : public QSortFilterProxyModel {
    Q_OBJECT
public:
    explicit MemberFilterProxy(QObject* parent = nullptr);

    void setFilterText(const QString& text);
    [[nodiscard]] QString filterText() const { return m_text; }

protected:
    [[nodiscard]] bool filterAcceptsRow(int sourceRow,
                                        const QModelIndex& sourceParent) const override;
    [[nodiscard]] bool lessThan(const QModelIndex& left, const QModelIndex& right) const override;

private:
    QString m_text;
};

}  // namespace ensil::ui

#include "widgets/member_filter_proxy.h"

#include <cmath>

#include "widgets/member_table_model.h"

namespace ensil::ui {

MemberFilterProxy::MemberFilterProxy(QObject* parent) : QSortFilterProxyModel(parent) {
    setSortRole(MemberTableModel::SortRole);
}

void MemberFilterProxy::setFilterText(const QString& text) {
    const QString trimmed = text.trimmed();
    if (trimmed == m_text) return;
    m_text = trimmed;
    invalidateRowsFilter();
}

bool MemberFilterProxy::filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const {
    if (m_text.isEmpty()) return true;
    const QAbstractItemModel* model = sourceModel();
    const QString name =
        model->index(sourceRow, MemberTableModel::Name, sourceParent).data().toString();
    if (name.contains(m_text, Qt::CaseInsensitive)) return true;
    bool isNumber = false;
    const int wanted = m_text.toInt(&isNumber);
    return isNumber &&
           model->index(sourceRow, MemberTableModel::Index, sourceParent).data().toInt() == wanted;
}

bool MemberFilterProxy::lessThan(const QModelIndex& left, const QModelIndex& right) const {
    const QVariant a = left.data(sortRole());
    const QVariant b = right.data(sortRole());
    // Unknown values last in ascending order (they compare as the largest).
    if (!a.isValid() || !b.isValid()) return a.isValid() && !b.isValid();
    if (a.typeId() == QMetaType::QString) {
        return QString::localeAwareCompare(a.toString(), b.toString()) < 0;
    }
    const double x = a.toDouble();
    const double y = b.toDouble();
    if (x != y) return x < y;
    // Equal keys keep member order, so sorting by cluster lists members in order.
    return left.row() < right.row();
}

}  // namespace ensil::ui

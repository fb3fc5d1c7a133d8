#include "widgets/cluster_list_model.h"

#include "workbench/member_selection.h"

namespace ensil::ui {

ClusterListModel::ClusterListModel(workbench::MemberSelection* selection, QObject* parent)
    : QAbstractTableModel(parent), m_selection(selection) {
    connect(selection, &workbench::MemberSelection::clustersAboutToChange, this,
            &ClusterListModel::beginResetModel);
    connect(selection, &workbench::MemberSelection::clustersChanged, this,
            &ClusterListModel::endResetModel);
    connect(selection, &workbench::MemberSelection::visibilityChanged, this, [this] {
        if (rowCount() == 0) return;
        emit dataChanged(index(0, Visible), index(rowCount() - 1, Visible), {Qt::CheckStateRole});
    });
}

int ClusterListModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : m_selection->clusterCount();
}

int ClusterListModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ClusterListModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) return {};
    const int c = index.row();
    switch (index.column()) {
        case Cluster:
            if (role == Qt::DisplayRole) {
                return tr("Cluster %1").arg(m_selection->clusterNumber(c));
            }
            if (role == Qt::DecorationRole) return m_selection->clusterColor(c);
            break;
        case Size:
            if (role == Qt::DisplayRole) {
                return static_cast<int>(m_selection->membersOfCluster(c).size());
            }
            if (role == Qt::TextAlignmentRole) {
                return QVariant::fromValue(Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
            }
            break;
        case Boxplot: {
            // "median, 2 outliers": where the ensemble's centre and its outlying members are.
            QStringList marks;
            QStringList outliers;
            bool median = false;
            for (const int m : m_selection->membersOfCluster(c)) {
                median = median || m_selection->isMedian(m);
                if (m_selection->isOutlier(m)) outliers << m_selection->name(m);
            }
            if (role == Qt::DisplayRole) {
                if (median) marks << tr("median");
                if (outliers.size() == 1) marks << tr("1 outlier");
                if (outliers.size() > 1) marks << tr("%1 outliers").arg(outliers.size());
                return marks.join(QStringLiteral(", "));
            }
            if (role == Qt::ToolTipRole && (median || !outliers.isEmpty())) {
                QStringList lines;
                if (median) {
                    lines << tr("Holds the median member %1 (the deepest)")
                                 .arg(m_selection->name(m_selection->medianMember()));
                }
                if (!outliers.isEmpty()) {
                    lines << tr("Outliers of the contour boxplot: %1")
                                 .arg(outliers.join(QStringLiteral(", ")));
                }
                return lines.join(QLatin1Char('\n'));
            }
            break;
        }
        case Visible:
            if (role == Qt::CheckStateRole) return m_selection->clusterVisibility(c);
            break;
        default:
            break;
    }
    if (role == Qt::ToolTipRole) {
        QStringList names;
        for (int m : m_selection->membersOfCluster(c)) names << m_selection->name(m);
        return names.join(QStringLiteral(", "));
    }
    return {};
}

QVariant ClusterListModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) {
        return QAbstractTableModel::headerData(section, orientation, role);
    }
    switch (section) {
        case Cluster:
            return tr("Cluster");
        case Size:
            return tr("Size");
        case Boxplot:
            return tr("Boxplot");
        case Visible:
            return tr("Visible");
        default:
            return {};
    }
}

Qt::ItemFlags ClusterListModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.isValid() && index.column() == Visible) f |= Qt::ItemIsUserCheckable;
    return f;
}

bool ClusterListModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid) || index.column() != Visible ||
        role != Qt::CheckStateRole) {
        return false;
    }
    // Qt's delegate turns a click on a partly checked box into Checked: show the whole cluster.
    m_selection->setClusterVisible(index.row(),
                                   static_cast<Qt::CheckState>(value.toInt()) != Qt::Unchecked);
    return true;
}

}  // namespace ensil::ui

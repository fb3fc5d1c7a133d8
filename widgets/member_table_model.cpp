#include "widgets/member_table_model.h"

#include <cmath>

#include "workbench/member_selection.h"

namespace ensil::ui {
namespace {
QVariant number(double value) { return std::isnan(value) ? QVariant() : QVariant(value); }

// The member's number as the file names it: "member 0" (ERA5's `number` coordinate runs 0-9)
// is number 0, so the # column and the name never disagree; names that carry no number (dates,
// file names) are counted from 1 in file order.

QString numberText(double value) {
    if (std::isnan(value)) return QStringLiteral("-");
    if (std::isinf(value)) return QStringLiteral("inf");
    return QString::number(value, 'g', 4);
}
}  // namespace

MemberTableModel::MemberTableModel(workbench::MemberSelection* selection, QObject* parent)
    : QAbstractTableModel(parent), m_selection(selection) {
    connect(selection, &workbench::MemberSelection::membersAboutToBeReset, this,
            &MemberTableModel::beginResetModel);
    connect(selection, &workbench::MemberSelection::membersReset, this,
            &MemberTableModel::endResetModel);
    connect(selection, &workbench::MemberSelection::clustersChanged, this, [this] {
        columnChanged(Cluster, {Qt::DisplayRole, Qt::DecorationRole, SortRole});
    });
    connect(selection, &workbench::MemberSelection::visibilityChanged, this, [this] {
        columnChanged(Visible, {Qt::CheckStateRole, SortRole});
    });
    connect(selection, &workbench::MemberSelection::hoverChanged, this, [this](int member) {
        rowChanged(m_hoveredRow, {Qt::BackgroundRole});
        m_hoveredRow = member;
        rowChanged(m_hoveredRow, {Qt::BackgroundRole});
    });
    connect(selection, &workbench::MemberSelection::membersReset, this,
            [this] { m_hoveredRow = m_selection->hovered(); });
}

void MemberTableModel::rowChanged(int row, const QList<int>& roles) {
    if (row < 0 || row >= rowCount()) return;
    emit dataChanged(index(row, 0), index(row, columnCount() - 1), roles);
}

void MemberTableModel::columnChanged(int column, const QList<int>& roles) {
    if (rowCount() == 0) return;
    emit dataChanged(index(0, column), index(rowCount() - 1, column), roles);
}

int MemberTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : m_selection->memberCount();
}

int MemberTableModel::columnCount(const QModelIndex& parent) const {
    if (parent.isValid()) return 0;
    return ColumnCount + (m_stepColumnsShown ? m_steps.stepCount() : 0);
}

void MemberTableModel::setSteps(const QStringList& labels) {
    if (m_stepColumnsShown) beginResetModel();
    m_steps.setSteps(labels);
    if (m_stepColumnsShown) endResetModel();
    emit stepsChanged(m_steps.stepCount());
}

void MemberTableModel::setStepClusters(int step, std::vector<int> identities) {
    if (!m_steps.setStepClusters(step, std::move(identities)) || !m_stepColumnsShown) return;
    // The step's column, and the next one's bold marks (who moved since this step).
    for (const int s : {step, step + 1}) {
        if (s < m_steps.stepCount()) {
            columnChanged(stepColumn(s), {Qt::DisplayRole, Qt::DecorationRole, Qt::FontRole,
                                          Qt::ToolTipRole, SortRole});
        }
    }
}

void MemberTableModel::setCurrentStep(int step) {
    const int before = m_steps.currentStep();
    m_steps.setCurrentStep(step);
    if (!m_stepColumnsShown || before == step) return;
    emit headerDataChanged(Qt::Horizontal, ColumnCount, columnCount() - 1);
}

void MemberTableModel::setStepColumnsShown(bool shown) {
    if (shown == m_stepColumnsShown) return;
    // Columns come and go: a reset, which the panel and its proxy follow like new members.
    beginResetModel();
    m_stepColumnsShown = shown;
    endResetModel();
}

QVariant MemberTableModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) return {};
    const int m = index.row();
    // The hovered row's tint spans the columns of the steps too.
    if (index.column() >= ColumnCount && role != Qt::BackgroundRole) {
        return m_steps.data(index.column() - ColumnCount, m, m_selection->name(m), role, SortRole);
    }
    const auto column = static_cast<Column>(index.column());
    if (role == Qt::DisplayRole || role == SortRole) {
        const bool sort = role == SortRole;
        switch (column) {
            case Index:
                // The member's number, 1..N in the ensemble's order, in every output (METHODS.md
                // "Numbers of members and clusters"); the name column says what the file calls it.
                return m + 1;
            case Name:
                return m_selection->name(m);
            case Cluster: {
                // The cluster's stable number, as the legend and the cluster list show it.
                const int c = m_selection->clusterNumber(m_selection->clusterOf(m));
                if (sort) return c;
                return c <= 0 ? QVariant() : QVariant(c);
            }
            case DistanceToMean:
                return sort ? number(m_selection->distanceToMean(m))
                            : QVariant(numberText(m_selection->distanceToMean(m)));
            case MeanOutlyingness:
                return sort ? number(m_selection->meanOutlyingness(m))
                            : QVariant(numberText(m_selection->meanOutlyingness(m)));
            case Depth: {
                // Sorted by the number; the median and the outliers are named beside it.
                const double depth = m_selection->depth(m);
                if (sort) return number(depth);
                const QString dot = QStringLiteral(" ") + QChar(0x00B7) + QStringLiteral(" ");
                if (m_selection->isMedian(m))
                    return workbench::depthText(depth) + dot + tr("median");
                if (m_selection->isOutlier(m))
                    return workbench::depthText(depth) + dot + tr("outlier");
                return workbench::depthText(depth);
            }
            case Visible:
                return sort ? QVariant(m_selection->isMemberVisible(m)) : QVariant();
            case ColumnCount:
                break;
        }
        return {};
    }
    if (role == Qt::CheckStateRole && column == Visible) {
        return m_selection->isMemberVisible(m) ? Qt::Checked : Qt::Unchecked;
    }
    if (role == Qt::DecorationRole && column == Cluster && m_selection->clusterOf(m) >= 0) {
        return m_selection->memberColor(m);
    }
    if (role == Qt::BackgroundRole && m == m_selection->hovered()) {
        // The member under the pointer (here, in the view or the dendrogram), tinted in its
        // cluster's colour.
        QColor tint = m_selection->memberColor(m);
        tint.setAlpha(90);
        return tint;
    }
    if (role == Qt::TextAlignmentRole && column != Name) {
        return QVariant::fromValue(Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
    }
    // A long name (a forecast date and time) is elided in the middle; the tip shows it whole.
    if (role == Qt::ToolTipRole && column == Name) return m_selection->name(m);
    if (role == Qt::ToolTipRole && column == DistanceToMean) {
        return tr("Distance of %1 to the mean member in the similarity measure")
            .arg(m_selection->name(m));
    }
    if (role == Qt::ToolTipRole && column == Depth) return depthToolTip(m);
    return {};
}

QString MemberTableModel::depthToolTip(int m) const {
    const QString name = m_selection->name(m);
    const double depth = m_selection->depth(m);
    if (std::isnan(depth)) {
        return tr("The depth of %1 comes with the isovalue's surfaces").arg(name);
    }
    const QString value = workbench::depthText(depth);
    if (m_selection->isMedian(m)) {
        return tr("%1 is the median of the contour boxplot: its isosurface is the deepest "
                  "(inclusion depth %2), the most central among the others")
            .arg(name, value);
    }
    if (m_selection->isOutlier(m)) {
        return tr("%1 is an outlier of the contour boxplot: its inclusion depth %2 lies below "
                  "the lower fence (Q1 - 1.5 IQR of all members' depths)")
            .arg(name, value);
    }
    return tr("Inclusion depth of %1's isosurface among the others: %2 (1 = most central, "
              "0 = no surface)")
        .arg(name, value);
}

QVariant MemberTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Horizontal && section >= ColumnCount) {
        return m_steps.headerData(section - ColumnCount, role);
    }
    if (orientation != Qt::Horizontal || (role != Qt::DisplayRole && role != Qt::ToolTipRole)) {
        return QAbstractTableModel::headerData(section, orientation, role);
    }
    // Short headers keep the table narrow enough for a side dock; the tooltips say it all.
    const bool tip = role == Qt::ToolTipRole;
    switch (section) {
        case Index:
            return tip ? tr("Member number, 1 to N in the ensemble's order, as every output gives "
                            "it")
                       : tr("#");
        case Name:
            return tip ? tr("Member name, from the file") : tr("Member");
        case Cluster:
            return tip ? tr("Cluster at the current cut") : tr("Cluster");
        case DistanceToMean:
            return tip ? tr("Distance to the mean member (similarity measure)") : tr("To mean");
        case MeanOutlyingness:
            return tip ? tr("Mean outlyingness over the member's isosurface") : tr("Outlying");
        case Depth:
            return tip ? tr("Inclusion depth of the member's isosurface among the others "
                            "(contour boxplot): 1 = most central, 0 = no surface; the deepest "
                            "is the median")
                       : tr("Depth");
        case Visible:
            return tip ? tr("Drawn in the view") : tr("Shown");
        default:
            return {};
    }
}

Qt::ItemFlags MemberTableModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.isValid() && index.column() == Visible) f |= Qt::ItemIsUserCheckable;
    return f;
}

bool MemberTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid) || index.column() != Visible ||
        role != Qt::CheckStateRole) {
        return false;
    }
    // The selection model emits visibilityChanged, which becomes dataChanged here.
    m_selection->setMemberVisible(index.row(),
                                  static_cast<Qt::CheckState>(value.toInt()) == Qt::Checked);
    return true;
}

}  // namespace ensil::ui

#include "widgets/cluster_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>

#include "widgets/cluster_list_model.h"
#include "workbench/member_selection.h"

namespace ensil::ui {
namespace {
struct LinkageChoice {
    prep::Linkage linkage;
    const char* label;
    const char* tip;
};
constexpr LinkageChoice kLinkages[] = {
    {prep::Linkage::Average, QT_TR_NOOP("Average"), QT_TR_NOOP("Mean distance between members")},
    {prep::Linkage::Single, QT_TR_NOOP("Single"), QT_TR_NOOP("Nearest members (chains)")},
    {prep::Linkage::Complete, QT_TR_NOOP("Complete"), QT_TR_NOOP("Farthest members (compact)")},
    {prep::Linkage::Ward, QT_TR_NOOP("Ward"), QT_TR_NOOP("Least growth of variance")},
};
}  // namespace

ClusterPanel::ClusterPanel(workbench::MemberSelection* selection, QWidget* parent)
    : QWidget(parent),
      m_selection(selection),
      m_model(new ClusterListModel(selection, this)),
      m_list(new QTableView(this)),
      m_solo(new QPushButton(tr("Solo"), this)),
      m_showAll(new QPushButton(tr("Show All"), this)),
      m_linkage(new QComboBox(this)) {
    m_list->setModel(m_model);
    m_list->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_list->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_list->verticalHeader()->hide();
    m_list->verticalHeader()->setDefaultSectionSize(m_list->fontMetrics().height() + 6);
    m_list->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_list->horizontalHeader()->setSectionResizeMode(ClusterListModel::Cluster,
                                                     QHeaderView::Stretch);
    for (const LinkageChoice& choice : kLinkages) {
        m_linkage->addItem(tr(choice.label), static_cast<int>(choice.linkage));
        m_linkage->setItemData(m_linkage->count() - 1, tr(choice.tip), Qt::ToolTipRole);
    }
    m_linkage->setToolTip(tr("How the distance between two clusters follows from their members'"));
    m_solo->setToolTip(tr("Show only the current cluster"));
    m_showAll->setToolTip(tr("Show every member"));

    auto* linkageRow = new QHBoxLayout;
    linkageRow->addWidget(new QLabel(tr("Linkage"), this));
    linkageRow->addWidget(m_linkage, 1);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_solo);
    buttons->addWidget(m_showAll);
    buttons->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(linkageRow);
    layout->addWidget(m_list, 1);
    layout->addLayout(buttons);

    connect(m_linkage, &QComboBox::currentIndexChanged, this,
            [this] { emit linkageChanged(linkage()); });
    connect(m_solo, &QPushButton::clicked, this, &ClusterPanel::soloCurrent);
    connect(m_showAll, &QPushButton::clicked, m_selection, &workbench::MemberSelection::showAll);
    connect(m_list->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &ClusterPanel::listSelectionChanged);
    connect(m_selection, &workbench::MemberSelection::selectionChanged, this,
            &ClusterPanel::showSharedSelection);
    connect(m_model, &QAbstractItemModel::modelReset, this, &ClusterPanel::showSharedSelection);
}

prep::Linkage ClusterPanel::linkage() const {
    return static_cast<prep::Linkage>(m_linkage->currentData().toInt());
}

void ClusterPanel::setLinkage(prep::Linkage linkage) {
    const QSignalBlocker block(m_linkage);
    m_linkage->setCurrentIndex(m_linkage->findData(static_cast<int>(linkage)));
}

QList<int> ClusterPanel::selectedClusters() const {
    QList<int> clusters;
    for (const QModelIndex& row : m_list->selectionModel()->selectedRows()) clusters << row.row();
    std::sort(clusters.begin(), clusters.end());
    return clusters;
}

void ClusterPanel::listSelectionChanged() {
    if (m_syncing) return;
    // The list speaks for whole clusters: its rows select exactly their members (a plain click
    // replaces the selection, as everywhere else).
    QList<int> members;
    for (int cluster : selectedClusters()) members << m_selection->membersOfCluster(cluster);
    m_selection->setSelection(members);
}

void ClusterPanel::showSharedSelection() {
    // A cluster is shown selected when every one of its members is.
    QList<int> wanted;
    for (int c = 0; c < m_model->rowCount(); ++c) {
        const QList<int> members = m_selection->membersOfCluster(c);
        const bool all =
            !members.isEmpty() && std::all_of(members.begin(), members.end(),
                                              [&](int m) { return m_selection->isSelected(m); });
        if (all) wanted << c;
    }
    if (wanted == selectedClusters()) return;
    QItemSelection rows;
    for (int c : wanted) {
        rows.select(m_model->index(c, 0), m_model->index(c, m_model->columnCount() - 1));
    }
    m_syncing = true;
    m_list->selectionModel()->select(rows, QItemSelectionModel::ClearAndSelect);
    m_syncing = false;
}

void ClusterPanel::soloCurrent() {
    const QModelIndex current = m_list->currentIndex();
    const QList<int> selected = selectedClusters();
    if (current.isValid()) {
        m_selection->soloCluster(current.row());
    } else if (!selected.isEmpty()) {
        m_selection->soloCluster(selected.front());
    }
}

}  // namespace ensil::ui

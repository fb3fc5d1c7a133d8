#include "widgets/member_table_panel.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <vector>

#include "widgets/member_filter_proxy.h"
#include "widgets/member_table_model.h"
#include "workbench/member_selection.h"

namespace ensil::ui {

MemberTablePanel::MemberTablePanel(workbench::MemberSelection* selection, QWidget* parent)
    : QWidget(parent),
      m_selection(selection),
      m_model(new MemberTableModel(selection, this)),
      m_proxy(new MemberFilterProxy(this)),
      m_filter(new QLineEdit(this)),
      m_stepsButton(new QToolButton(this)),
      m_table(new QTableView(this)) {
    m_proxy->setSourceModel(m_model);
    m_filter->setPlaceholderText(tr("Filter members by name or #"));
    m_filter->setClearButtonEnabled(true);
    // Resets, new sort orders and filters rebuild the rows, and the table's selection loses
    // rows on the way: that is not the user's doing, so it is ignored while it happens and the
    // shared selection is shown again afterwards. The order of connections matters: the pauses
    // are connected before the view's selection model exists, so they run before it reacts,
    // and the resumes after, so they run after it.
    const auto pause = [this] { m_syncing = true; };
    connect(m_proxy, &QAbstractItemModel::modelAboutToBeReset, this, pause);
    connect(m_proxy, &QAbstractItemModel::layoutAboutToBeChanged, this, pause);
    connect(m_proxy, &QAbstractItemModel::rowsAboutToBeRemoved, this, pause);
    connect(m_proxy, &QAbstractItemModel::rowsAboutToBeInserted, this, pause);
    m_table->setModel(m_proxy);
    // Names that differ at their end (dates, run numbers) stay told apart when cut short.
    m_table->setTextElideMode(Qt::ElideMiddle);
    const auto resume = [this] {
        m_syncing = false;
        showSharedSelection();
    };
    connect(m_proxy, &QAbstractItemModel::modelReset, this, resume);
    connect(m_proxy, &QAbstractItemModel::modelReset, this, &MemberTablePanel::fitColumns);
    connect(m_proxy, &QAbstractItemModel::layoutChanged, this, resume);
    connect(m_proxy, &QAbstractItemModel::rowsRemoved, this, resume);
    connect(m_proxy, &QAbstractItemModel::rowsInserted, this, resume);
    m_table->setSortingEnabled(true);
    m_table->sortByColumn(MemberTableModel::Index, Qt::AscendingOrder);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    // Columns are fitted to their contents when new members arrive, not on every change:
    // ResizeToContents would measure every row each time the cut line moves.
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_table->horizontalHeader()->setSectionResizeMode(MemberTableModel::Name, QHeaderView::Stretch);
    // The column sorted by now shows the arrow: room is made for it, never taken.
    connect(m_table->horizontalHeader(), &QHeaderView::sortIndicatorChanged, this, [this](int c) {
        QHeaderView* header = m_table->horizontalHeader();
        if (c < 0 || c == MemberTableModel::Name) return;
        header->resizeSection(c, std::max(header->sectionSize(c), header->sectionSizeHint(c)));
    });
    m_table->setMouseTracking(true);
    m_table->viewport()->installEventFilter(this);

    m_stepsButton->setText(tr("Per Step"));
    m_stepsButton->setCheckable(true);
    m_stepsButton->setToolTip(
        tr("Show each member's cluster at every time step as a column "
           "(bold: the member moved to another cluster there)"));
    m_stepsButton->setVisible(false);  // for data with time steps
    connect(m_stepsButton, &QToolButton::toggled, m_model, &MemberTableModel::setStepColumnsShown);
    connect(m_model, &MemberTableModel::stepsChanged, this,
            [this](int count) { m_stepsButton->setVisible(count > 1); });

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* top = new QHBoxLayout;
    top->addWidget(m_filter);
    top->addWidget(m_stepsButton);
    layout->addLayout(top);
    layout->addWidget(m_table);

    connect(m_filter, &QLineEdit::textChanged, m_proxy, &MemberFilterProxy::setFilterText);
    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &MemberTablePanel::tableSelectionChanged);
    connect(m_selection, &workbench::MemberSelection::selectionChanged, this,
            &MemberTablePanel::showSharedSelection);
}

void MemberTablePanel::fitColumns() {
    // Every column but the name's fits its cells and its header's text. QHeaderView's own fit
    // reserves room for the sort arrow in every header, though only the sorted column shows it:
    // some 25 pixels a column, which in a side dock were all the names had left. So the headers
    // are measured without it, and the sorted column alone gets it.
    QHeaderView* header = m_table->horizontalHeader();
    const int columns = m_model->columnCount();
    std::vector<int> plain(static_cast<std::size_t>(columns));
    header->setSortIndicatorShown(false);
    for (int c = 0; c < columns; ++c)
        plain.at(static_cast<std::size_t>(c)) = header->sectionSizeHint(c);
    header->setSortIndicatorShown(true);
    for (int c = 0; c < columns; ++c) {
        if (c == MemberTableModel::Name) continue;
        int width = c == header->sortIndicatorSection() ? header->sectionSizeHint(c)
                                                        : plain.at(static_cast<std::size_t>(c));
        const int grid = m_table->showGrid() ? 1 : 0;
        for (int row = 0; row < m_proxy->rowCount(); ++row) {
            width =
                std::max(width, m_table->sizeHintForIndex(m_proxy->index(row, c)).width() + grid);
        }
        header->resizeSection(c, width);
    }
}

int MemberTablePanel::memberAtRow(int row) const {
    const QModelIndex source = m_proxy->mapToSource(m_proxy->index(row, 0));
    return source.isValid() ? source.row() : -1;
}

int MemberTablePanel::rowOfMember(int member) const {
    return m_proxy->mapFromSource(m_model->index(member, 0)).row();
}

void MemberTablePanel::tableSelectionChanged() {
    if (m_syncing) return;
    // Members the filter hides keep their selection; the rows shown say what is selected.
    QList<int> members;
    for (int m : m_selection->selectedMembers()) {
        if (rowOfMember(m) < 0) members << m;
    }
    for (const QModelIndex& row : m_table->selectionModel()->selectedRows()) {
        members << m_proxy->mapToSource(row).row();
    }
    m_selection->setSelection(members);
}

void MemberTablePanel::showSharedSelection() {
    QItemSelection rows;
    QList<int> shownRows;
    int first = -1;
    for (int member : m_selection->selectedMembers()) {
        const int row = rowOfMember(member);
        if (row < 0) continue;
        rows.select(m_proxy->index(row, 0), m_proxy->index(row, m_proxy->columnCount() - 1));
        shownRows << row;
        if (first < 0 || row < first) first = row;
    }
    // When the table made this selection it already shows it; selecting again would disturb a
    // drag or Shift-click in progress.
    QList<int> tableRows;
    for (const QModelIndex& row : m_table->selectionModel()->selectedRows()) {
        tableRows << row.row();
    }
    std::sort(shownRows.begin(), shownRows.end());
    std::sort(tableRows.begin(), tableRows.end());
    if (shownRows == tableRows) return;
    const bool wasSyncing = m_syncing;
    m_syncing = true;
    m_table->selectionModel()->select(rows, QItemSelectionModel::ClearAndSelect);
    m_syncing = wasSyncing;
    if (first >= 0) m_table->scrollTo(m_proxy->index(first, 0));
}

bool MemberTablePanel::eventFilter(QObject* watched, QEvent* event) {
    // Hover is followed here rather than through QAbstractItemView::entered, which never
    // reports leaving the rows for the empty space below them.
    if (watched == m_table->viewport() && event->type() == QEvent::MouseMove) {
        const QModelIndex index =
            m_table->indexAt(static_cast<QMouseEvent*>(event)->position().toPoint());
        m_selection->setHovered(index.isValid() ? memberAtRow(index.row()) : -1);
    } else if (watched == m_table->viewport() && event->type() == QEvent::Leave) {
        m_selection->setHovered(-1);
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace ensil::ui

// The member table dock: a filter box over a sortable table of members (MemberTableModel
// through MemberFilterProxy). Rows selected in the table are the shared
// workbench::MemberSelection's selection and the other way round; members hidden by the filter keep
// their selection. Hovering a row hovers its member. For data with time steps, a button beside the
// filter shows each member's cluster per step as columns. GUI thread only.
#pragma once

#include <QWidget>

class QItemSelection;
class QLineEdit;
class QTableView;
class QToolButton;

namespace ensil::workbench {
class MemberSelection;
}  // namespace ensil::workbench

namespace ensil::ui {

class MemberTableModel;
class MemberFilterProxy;

class MemberTablePanel : public QWidget {
    Q_OBJECT
public:
    explicit MemberTablePanel(workbench::MemberSelection* selection, QWidget* parent = nullptr);

    [[nodiscard]] QTableView* table() const { return m_table; }
    [[nodiscard]] QLineEdit* filterBox() const { return m_filter; }
    [[nodiscard]] MemberTableModel* model() const { return m_model; }
    [[nodiscard]] MemberFilterProxy* proxy() const { return m_proxy; }
    // Shows or hides the columns of each member's cluster per time step (data with steps).
    [[nodiscard]] QToolButton* stepsButton() const { return m_stepsButton; }
    // The member shown in a row of the table as sorted and filtered now.
    [[nodiscard]] int memberAtRow(int row) const;
    [[nodiscard]] int rowOfMember(int member) const;  // -1 when filtered out

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void tableSelectionChanged();
    void showSharedSelection();
    // Fits the columns (all but the name's, which takes the rest) when new members arrive.
    void fitColumns();

    workbench::MemberSelection* m_selection;
    MemberTableModel* m_model;
    MemberFilterProxy* m_proxy;
    QLineEdit* m_filter;
    QToolButton* m_stepsButton;
    QTableView* m_table;
    bool m_syncing = false;  // true while the table is being set from the shared selection
};

}  // namespace ensil::ui

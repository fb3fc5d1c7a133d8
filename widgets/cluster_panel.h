// The cluster list dock: one row per cluster of the current cut (colour, size, visibility
// checkbox), Solo (show only the current cluster) and Show All buttons, and the linkage the
// merge tree is built with. Selecting clusters selects their members in the shared
// workbench::MemberSelection; a cluster shows as selected when all its members are. GUI thread
// only.
#pragma once

#include <QWidget>

#include "preprocessing/clustering.h"

class QComboBox;
class QPushButton;
class QTableView;

namespace ensil::workbench {
class MemberSelection;
}  // namespace ensil::workbench

namespace ensil::ui {

class ClusterListModel;

class ClusterPanel : public QWidget {
    Q_OBJECT
public:
    explicit ClusterPanel(workbench::MemberSelection* selection, QWidget* parent = nullptr);

    [[nodiscard]] QTableView* list() const { return m_list; }
    [[nodiscard]] ClusterListModel* model() const { return m_model; }
    [[nodiscard]] QComboBox* linkageBox() const { return m_linkage; }
    [[nodiscard]] QPushButton* soloButton() const { return m_solo; }
    [[nodiscard]] QPushButton* showAllButton() const { return m_showAll; }
    [[nodiscard]] prep::Linkage linkage() const;
    // Sets the combo box without emitting linkageChanged.
    void setLinkage(prep::Linkage linkage);
    // Clusters shown as selected now (ascending).
    [[nodiscard]] QList<int> selectedClusters() const;

signals:
    void linkageChanged(ensil::prep::Linkage linkage);

private:
    void listSelectionChanged();
    void showSharedSelection();
    void soloCurrent();

    workbench::MemberSelection* m_selection;
    ClusterListModel* m_model;
    QTableView* m_list;
    QPushButton* m_solo;
    QPushButton* m_showAll;
    QComboBox* m_linkage;
    bool m_syncing = false;  // true while the list is being set from the shared selection
};

}  // namespace ensil::ui

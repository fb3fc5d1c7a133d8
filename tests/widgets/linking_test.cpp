// The panels on one shared workbench::MemberSelection, the way the workbench docks them: whatever
// is selected or cut in one shows in the others, with no panel calling another.
#include <gtest/gtest.h>

#include <QApplication>
#include <QItemSelectionModel>
#include <QTableView>
#include <QTest>
#include <algorithm>

#include "gl/palette.h"
#include "panel_fixtures.h"
#include "widgets/cluster_list_model.h"
#include "widgets/cluster_panel.h"
#include "widgets/dendrogram_view.h"
#include "widgets/member_filter_proxy.h"
#include "widgets/member_table_model.h"
#include "widgets/member_table_panel.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {
class LinkedPanels : public ::testing::Test {
protected:
    void SetUp() override {
        test::loadTwoGroups(selection, 2);
        for (QWidget* w : std::initializer_list<QWidget*>{&table, &clusters, &dendrogram}) {
            w->resize(600, 300);
            w->show();
            ASSERT_TRUE(QTest::qWaitForWindowExposed(w));
        }
    }

    QList<int> tableSelection() const {
        QList<int> members;
        for (const QModelIndex& row : table.table()->selectionModel()->selectedRows()) {
            members << table.memberAtRow(row.row());
        }
        std::sort(members.begin(), members.end());
        return members;
    }

    // The colour the dendrogram draws under a member's leaf: its cluster's when selected.
    QColor dendrogramMarker(int member) {
        QApplication::processEvents();  // the repaint the last change asked for
        const QImage image = dendrogram.viewport()->grab().toImage();
        const ui::DendrogramFrame frame = dendrogram.frame();
        const double radius = std::clamp(frame.leafWidth * 0.3, 2.0, 5.0);
        const QPointF at(frame.pixelX(dendrogram.layout().x(member)),
                         frame.plot.bottom() + radius + 1.0);
        return image.pixelColor((at * image.devicePixelRatio()).toPoint());
    }

    void selectTableRows(const QList<int>& members) {
        QItemSelection rows;
        for (int m : members) {
            const int row = table.rowOfMember(m);
            rows.select(table.proxy()->index(row, 0),
                        table.proxy()->index(row, ui::MemberTableModel::ColumnCount - 1));
        }
        table.table()->selectionModel()->select(rows, QItemSelectionModel::ClearAndSelect);
    }

    workbench::MemberSelection selection;
    ui::MemberTablePanel table{&selection};
    ui::ClusterPanel clusters{&selection};
    ui::DendrogramView dendrogram{&selection};
};
}  // namespace

TEST_F(LinkedPanels, SelectingInTheTableSelectsInTheClusterListAndTheDendrogram) {
    selectTableRows({1, 3, 5});
    EXPECT_EQ(selection.selectedMembers(), (QList<int>{1, 3, 5}));
    EXPECT_EQ(clusters.selectedClusters(), QList<int>{selection.clusterOf(1)});
    EXPECT_EQ(dendrogramMarker(3).rgb(), selection.memberColor(3).rgb());
    EXPECT_NE(dendrogramMarker(0).rgb(), selection.memberColor(0).rgb()) << "0 is not selected";
    for (int m : {1, 3, 5}) EXPECT_TRUE(selection.appearance()[m].selected) << "the view's look";
}

TEST_F(LinkedPanels, ClickingInTheDendrogramSelectsInTheTableAndTheClusterList) {
    const auto& layout = dendrogram.layout();
    int group = -1;  // the branch holding members 0, 2 and 4
    for (int node = layout.memberCount(); node < layout.nodeCount(); ++node) {
        if (layout.memberCountOf(node) == 3 && layout.membersOf(node).contains(0)) group = node;
    }
    ASSERT_GE(group, 0);
    const QPoint bar = dendrogram.frame().toPixel(layout.x(group), layout.height(group)).toPoint();
    QTest::mouseClick(dendrogram.viewport(), Qt::LeftButton, Qt::NoModifier, bar);
    EXPECT_EQ(tableSelection(), (QList<int>{0, 2, 4}));
    EXPECT_EQ(clusters.selectedClusters(), QList<int>{selection.clusterOf(0)});
}

TEST_F(LinkedPanels, SelectingAClusterSelectsInTheTableAndTheDendrogram) {
    clusters.list()->selectRow(selection.clusterOf(1));
    EXPECT_EQ(tableSelection(), (QList<int>{1, 3, 5}));
    EXPECT_EQ(dendrogramMarker(5).rgb(), selection.memberColor(5).rgb());
    // And back: a plain click on a member row replaces the cluster's selection.
    selectTableRows({2});
    EXPECT_TRUE(clusters.selectedClusters().isEmpty());
    EXPECT_EQ(selection.selectedMembers(), QList<int>{2});
}

TEST_F(LinkedPanels, DraggingTheCutLineUpdatesTheClusterListTheTableAndTheColours) {
    const ui::DendrogramFrame frame = dendrogram.frame();
    const auto& layout = dendrogram.layout();
    const int x = static_cast<int>(frame.plot.right()) - 20;
    QTest::mousePress(dendrogram.viewport(), Qt::LeftButton, Qt::NoModifier,
                      QPoint(x, static_cast<int>(std::lround(frame.pixelY(layout.cutHeight(2))))));
    QTest::mouseRelease(dendrogram.viewport(), Qt::LeftButton, Qt::NoModifier,
                        QPoint(x, static_cast<int>(frame.pixelY(layout.cutHeight(4)))));
    ASSERT_EQ(selection.clusterCount(), 4);
    EXPECT_EQ(clusters.model()->rowCount(), 4);
    int total = 0;
    for (int c = 0; c < 4; ++c) {
        total += clusters.model()->index(c, ui::ClusterListModel::Size).data().toInt();
    }
    EXPECT_EQ(total, 6);
    const auto look = selection.appearance();
    for (int m = 0; m < 6; ++m) {
        const QModelIndex cell = table.model()->index(m, ui::MemberTableModel::Cluster);
        const int identity = selection.identityOf(selection.clusterOf(m));
        EXPECT_EQ(cell.data().toInt(), identity + 1);
        EXPECT_EQ(cell.data(Qt::DecorationRole).value<QColor>(), selection.memberColor(m));
        EXPECT_EQ(look[static_cast<std::size_t>(m)].color, gl::clusterColor(identity));
    }
}

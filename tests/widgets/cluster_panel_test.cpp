#include "widgets/cluster_panel.h"

#include <gtest/gtest.h>

#include <QComboBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>

#include "panel_fixtures.h"
#include "widgets/cluster_list_model.h"
#include "workbench/member_selection.h"

using namespace ensil;
using ui::ClusterListModel;

TEST(ClusterListModel, KeepsQtsModelContractThroughEveryChange) {
    workbench::MemberSelection s;
    ClusterListModel model(&s);
    test::ModelContractCheck check(&model);
    test::loadTwoGroups(s);
    for (int k : {1, 6, 3}) s.setClusterCount(k);
    s.setClusterVisible(1, false);
    s.soloCluster(2);
    s.showAll();
    s.setMembers(test::figuresOnALine({1.0, 2.0, 3.0}));
    s.setTree(test::treeOnALine({1.0, 2.0, 3.0}));
    s.setMembers({});
    EXPECT_TRUE(test::ModelContractCheck::failures().isEmpty())
        << test::ModelContractCheck::failures().join('\n').toStdString();
}

TEST(ClusterListModel, ShowsColourSizeAndVisibility) {
    workbench::MemberSelection s;
    ClusterListModel model(&s);
    EXPECT_EQ(model.rowCount(), 0) << "no tree, no clusters";
    test::loadTwoGroups(s, 3);  // {0, 2, 4} stays, {1, 3, 5} splits into {1, 3} and {5}
    ASSERT_EQ(model.rowCount(), 3);
    QList<int> sizes;
    for (int c = 0; c < 3; ++c) {
        sizes << model.index(c, ClusterListModel::Size).data().toInt();
        EXPECT_EQ(
            model.index(c, ClusterListModel::Cluster).data(Qt::DecorationRole).value<QColor>(),
            s.clusterColor(c));
    }
    std::sort(sizes.begin(), sizes.end());
    EXPECT_EQ(sizes, (QList<int>{1, 2, 3}));

    const int c = s.clusterOf(1);
    const QModelIndex box = model.index(c, ClusterListModel::Visible);
    s.setMemberVisible(1, false);
    EXPECT_EQ(box.data(Qt::CheckStateRole).toInt(), Qt::PartiallyChecked);
    ASSERT_TRUE(model.setData(box, Qt::Checked, Qt::CheckStateRole));
    EXPECT_TRUE(s.isMemberVisible(1));
    ASSERT_TRUE(model.setData(box, Qt::Unchecked, Qt::CheckStateRole));
    EXPECT_FALSE(s.isMemberVisible(1));
    EXPECT_FALSE(s.isMemberVisible(3));
    EXPECT_TRUE(s.isMemberVisible(5));
}

TEST(ClusterPanel, SelectingAClusterSelectsItsMembersAndTheOtherWayRound) {
    workbench::MemberSelection s;
    ui::ClusterPanel panel(&s);
    test::loadTwoGroups(s);
    panel.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
    const int b = s.clusterOf(1);
    panel.list()->selectRow(b);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{1, 3, 5}));

    s.setSelection({0, 2});  // part of a cluster: no cluster is wholly selected
    EXPECT_TRUE(panel.selectedClusters().isEmpty());
    s.click({4}, Qt::ShiftModifier);
    EXPECT_EQ(panel.selectedClusters(), (QList<int>{s.clusterOf(0)}));
    EXPECT_EQ(s.selectedMembers(), (QList<int>{0, 2, 4})) << "showing it must not feed back";
}

TEST(ClusterPanel, SoloShowsOnlyTheCurrentClusterAndShowAllEverything) {
    workbench::MemberSelection s;
    ui::ClusterPanel panel(&s);
    test::loadTwoGroups(s);
    const int a = s.clusterOf(0);
    panel.list()->setCurrentIndex(panel.model()->index(a, ClusterListModel::Cluster));
    panel.soloButton()->click();
    for (int m = 0; m < 6; ++m) EXPECT_EQ(s.isMemberVisible(m), s.clusterOf(m) == a) << m;
    panel.showAllButton()->click();
    for (int m = 0; m < 6; ++m) EXPECT_TRUE(s.isMemberVisible(m));
}

TEST(ClusterPanel, OffersEveryLinkageThePreprocessingKnows) {
    workbench::MemberSelection s;
    ui::ClusterPanel panel(&s);
    EXPECT_EQ(panel.linkage(), prep::Linkage::Average);
    QSignalSpy changed(&panel, &ui::ClusterPanel::linkageChanged);
    QStringList names;
    for (int i = 0; i < panel.linkageBox()->count(); ++i) {
        panel.linkageBox()->setCurrentIndex(i);
        names << QString::fromStdString(prep::linkageName(panel.linkage()));
    }
    EXPECT_EQ(names, (QStringList{"average", "single", "complete", "ward"}));
    EXPECT_EQ(changed.count(), 3);
    EXPECT_EQ(changed.back().front().value<prep::Linkage>(), prep::Linkage::Ward);
    panel.setLinkage(prep::Linkage::Single);
    EXPECT_EQ(panel.linkage(), prep::Linkage::Single);
    EXPECT_EQ(changed.count(), 3) << "setting it from the program is not the user's choice";
}

TEST(ClusterListModel, SaysWhichClusterHoldsTheMedianAndWhichTheOutliers) {
    workbench::MemberSelection s;
    ClusterListModel model(&s);
    // Two groups, {0, 2, 4} and {1, 3, 5}; member 4 is the median, 3 and 5 are outliers.
    workbench::MemberFigures figures = test::figuresOnALine(test::kTwoGroups);
    figures.depth = {0.5, 0.4, 0.6, 0.1, 0.9, 0.05};
    figures.median = 4;
    figures.outliers = {3, 5};
    s.setMembers(figures);
    s.setTree(test::treeOnALine(test::kTwoGroups));
    s.setClusterCount(2);
    const auto marks = [&](int member) {
        return model.index(s.clusterOf(member), ClusterListModel::Boxplot).data().toString();
    };
    EXPECT_EQ(marks(4), QStringLiteral("median"));
    EXPECT_EQ(marks(1), QStringLiteral("2 outliers"));
    EXPECT_TRUE(model.index(s.clusterOf(1), ClusterListModel::Boxplot)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("m3, m5")));
    figures.outliers = {3};
    s.setMembers(figures);
    EXPECT_EQ(marks(1), QStringLiteral("1 outlier"));
    s.setClusterCount(1);
    EXPECT_EQ(marks(0), QStringLiteral("median, 1 outlier"));
    EXPECT_EQ(model.headerData(ClusterListModel::Boxplot, Qt::Horizontal, Qt::DisplayRole),
              QStringLiteral("Boxplot"));
}

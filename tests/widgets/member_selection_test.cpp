#include "widgets/member_selection.h"

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <stdexcept>

#include "gl/palette.h"
#include "panel_fixtures.h"

using namespace ensil;
using ui::MemberSelection;

TEST(MemberSelection, CutsTheTreeIntoTheRequestedClusters) {
    MemberSelection s;
    test::loadTwoGroups(s, 2);
    ASSERT_EQ(s.clusterCount(), 2);
    EXPECT_EQ(s.membersOfCluster(s.clusterOf(0)), (QList<int>{0, 2, 4}));
    EXPECT_EQ(s.membersOfCluster(s.clusterOf(1)), (QList<int>{1, 3, 5}));
    QSignalSpy changed(&s, &MemberSelection::clustersChanged);
    s.setClusterCount(1);
    EXPECT_EQ(changed.count(), 1);
    for (int m = 0; m < 6; ++m) EXPECT_EQ(s.clusterOf(m), 0);
    s.setClusterCount(99);  // more clusters than members: every member its own
    EXPECT_EQ(s.clusterCount(), 6);
}

TEST(MemberSelection, PlainClickReplacesShiftAddsCtrlToggles) {
    MemberSelection s;
    test::loadTwoGroups(s);
    QSignalSpy changed(&s, &MemberSelection::selectionChanged);
    s.click({1, 3}, Qt::NoModifier);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{1, 3}));
    s.click({0}, Qt::ShiftModifier);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{0, 1, 3}));
    s.click({3, 4}, Qt::ControlModifier);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{0, 1, 4}));
    s.click({2}, Qt::NoModifier);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{2}));
    s.click({}, Qt::NoModifier);  // a click on the background
    EXPECT_TRUE(s.selectedMembers().isEmpty());
    EXPECT_EQ(changed.count(), 5);
    s.click({}, Qt::ShiftModifier);     // adding nothing changes nothing
    s.click({-1, 42}, Qt::NoModifier);  // members that do not exist are ignored
    EXPECT_EQ(changed.count(), 5);
}

TEST(MemberSelection, ClusterVisibilityFollowsItsMembers) {
    MemberSelection s;
    test::loadTwoGroups(s);
    const int a = s.clusterOf(0);
    const int b = s.clusterOf(1);
    EXPECT_EQ(s.clusterVisibility(a), Qt::Checked);
    s.setMemberVisible(2, false);
    EXPECT_EQ(s.clusterVisibility(a), Qt::PartiallyChecked);
    s.setClusterVisible(a, false);
    EXPECT_EQ(s.clusterVisibility(a), Qt::Unchecked);
    EXPECT_FALSE(s.isMemberVisible(0));
    s.soloCluster(a);
    EXPECT_EQ(s.clusterVisibility(a), Qt::Checked);
    EXPECT_EQ(s.clusterVisibility(b), Qt::Unchecked);
    QSignalSpy changed(&s, &MemberSelection::visibilityChanged);
    s.showAll();
    EXPECT_EQ(changed.count(), 1);
    for (int m = 0; m < 6; ++m) EXPECT_TRUE(s.isMemberVisible(m));
    s.showAll();
    EXPECT_EQ(changed.count(), 1) << "nothing changed, nothing to tell";
}

TEST(MemberSelection, AppearanceCarriesColourVisibilityAndSelection) {
    MemberSelection s;
    test::loadTwoGroups(s);
    s.setMemberVisible(3, false);
    s.setSelection({4});
    const auto look = s.appearance();
    ASSERT_EQ(look.size(), 6u);
    for (int m = 0; m < 6; ++m) {
        const auto& a = look[static_cast<std::size_t>(m)];
        EXPECT_EQ(a.cluster, s.clusterOf(m));
        EXPECT_EQ(a.color, gl::clusterColor(s.clusterOf(m)));
        EXPECT_EQ(a.visible, m != 3);
        EXPECT_EQ(a.selected, m == 4);
    }
    EXPECT_NE(look[0].color, look[1].color) << "two clusters, two colours";
}

TEST(MemberSelection, ANewIsovalueKeepsTheSelectionNewMembersStartAfresh) {
    MemberSelection s;
    test::loadTwoGroups(s);
    s.setSelection({1, 5});
    s.setMemberVisible(0, false);
    s.setHovered(3);
    auto figures = test::figuresOnALine(test::kTwoGroups);
    figures.distanceToMean[0] = 7.0;
    s.setMembers(figures);  // the same members, other figures
    EXPECT_EQ(s.selectedMembers(), (QList<int>{1, 5}));
    EXPECT_FALSE(s.isMemberVisible(0));
    EXPECT_EQ(s.hovered(), 3);
    EXPECT_DOUBLE_EQ(s.distanceToMean(0), 7.0);

    QSignalSpy reset(&s, &MemberSelection::membersReset);
    QSignalSpy hover(&s, &MemberSelection::hoverChanged);
    figures.names[0] = QStringLiteral("another");
    s.setMembers(figures);
    EXPECT_EQ(reset.count(), 1);
    EXPECT_TRUE(s.selectedMembers().isEmpty());
    EXPECT_TRUE(s.isMemberVisible(0));
    EXPECT_EQ(s.hovered(), -1);
    EXPECT_EQ(hover.count(), 1);
    EXPECT_FALSE(s.isClustered()) << "the old tree does not describe new members";
    EXPECT_EQ(s.clusterOf(0), -1);
}

TEST(MemberSelection, RejectsFiguresAndTreesOfAnotherSize) {
    MemberSelection s;
    auto figures = test::figuresOnALine(test::kTwoGroups);
    figures.distanceToMean.pop_back();
    EXPECT_THROW(s.setMembers(figures), std::invalid_argument);
    s.setMembers(test::figuresOnALine(test::kTwoGroups));
    try {
        s.setTree(test::treeOnALine({0.0, 1.0, 2.0}));
        FAIL() << "a tree of three members was accepted for six";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "the merge tree clusters 3 members but there are 6");
    }
    EXPECT_EQ(s.memberCount(), 6);
}

TEST(MemberSelection, HoverIgnoresMembersThatDoNotExist) {
    MemberSelection s;
    test::loadTwoGroups(s);
    QSignalSpy hover(&s, &MemberSelection::hoverChanged);
    s.setHovered(2);
    s.setHovered(2);
    s.setHovered(17);
    ASSERT_EQ(hover.count(), 2);
    EXPECT_EQ(hover.at(1).at(0).toInt(), -1);
    EXPECT_EQ(s.hovered(), -1);
}

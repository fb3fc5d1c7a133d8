#include "workbench/member_selection.h"

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <stdexcept>
#include <vector>

#include "gl/palette.h"
#include "session/session_model.h"
#include "tests/workbench/selection_fixtures.h"

using namespace ensil;
using workbench::MemberSelection;

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

namespace {
std::vector<QColor> colours(const MemberSelection& s) {
    std::vector<QColor> c;
    for (int m = 0; m < s.memberCount(); ++m) c.push_back(s.memberColor(m));
    return c;
}
}  // namespace

TEST(MemberSelection, ColoursKeepTheirMeaningWhenTheCountGoesUpAndDown) {
    MemberSelection s;
    test::loadTwoGroups(s, 2);
    const std::vector<QColor> two = colours(s);
    s.setClusterCount(3);  // {1, 3, 5} splits into {1, 3} and {5}
    const std::vector<QColor> three = colours(s);
    EXPECT_EQ(three[0], two[0]) << "the group that did not split keeps its colour";
    EXPECT_EQ(three[1], two[1]) << "the larger part of the split keeps its colour";
    EXPECT_EQ(three[3], two[3]);
    EXPECT_NE(three[5], two[5]) << "the smaller part takes a new one";
    EXPECT_EQ(s.clusterNumber(s.clusterOf(5)), 3);
    s.setClusterCount(2);
    EXPECT_EQ(colours(s), two) << "merging back gives the colours back";
}

TEST(MemberSelection, ANewTreeOfTheSameMembersKeepsColoursByTheirMembers) {
    MemberSelection s;
    test::loadTwoGroups(s, 2);
    const std::vector<QColor> before = colours(s);
    // Another isovalue: the two groups swap places along the line, so the dendrogram (and the
    // labels 0, 1 of the cut) come in the other order; the members of each group are the same.
    s.setTree(test::treeOnALine({10.0, 0.0, 10.5, 0.7, 11.5, 2.0}));
    EXPECT_EQ(colours(s), before);
    // Member 4 moves to the other group, which becomes the larger one. From the tree alone the
    // larger group would take the first colour; matched by shared members, each group keeps
    // its colour and only member 4 changes.
    s.setTree(test::treeOnALine({0.0, 10.0, 0.5, 10.7, 11.0, 12.0}));
    const std::vector<QColor> after = colours(s);
    for (const int m : {0, 1, 2, 3, 5}) EXPECT_EQ(after[m], before[m]) << m;
    EXPECT_EQ(after[4], before[1]);
}

// One truth: what is hidden and selected is the session's. The selection writes its edits there,
// and shows whatever the session says, whoever changed it (undo, a project).
TEST(MemberSelection, HiddenAndSelectedMembersAreTheSessionsBothWays) {
    session::SessionModel model;
    MemberSelection s(&model);
    test::loadTwoGroups(s);
    s.setMemberVisible(3, false);
    s.click({1, 4}, Qt::NoModifier);
    EXPECT_EQ(model.state().hiddenMembers, std::vector<int>{3});
    EXPECT_EQ(model.state().selection, (std::vector<int>{1, 4}));

    QSignalSpy visibility(&s, &MemberSelection::visibilityChanged);
    QSignalSpy selection(&s, &MemberSelection::selectionChanged);
    model.update([](session::SessionState& state) {
        state.hiddenMembers = {0, 5};
        state.selection = {2};
    });
    EXPECT_EQ(visibility.count(), 1);
    EXPECT_EQ(selection.count(), 1);
    EXPECT_FALSE(s.isMemberVisible(0));
    EXPECT_TRUE(s.isMemberVisible(3));
    EXPECT_FALSE(s.isMemberVisible(5));
    EXPECT_EQ(s.selectedMembers(), QList<int>{2});
    // A change of another part says nothing of the members.
    model.update([](session::SessionState& state) { state.clusters = 4; });
    EXPECT_EQ(visibility.count(), 1);
    EXPECT_EQ(selection.count(), 1);
}

TEST(MemberSelection, AClusterHiddenInTheSessionHidesItsMembersUnderTheClustersShown) {
    session::SessionModel model;
    MemberSelection s(&model);
    test::loadTwoGroups(s);
    const int farGroup = s.clusterOf(1);  // {1, 3, 5}
    model.update([farGroup](session::SessionState& state) { state.hiddenClusters = {farGroup}; });
    EXPECT_EQ(s.clusterVisibility(farGroup), Qt::Unchecked);
    EXPECT_TRUE(s.isMemberVisible(0));
    EXPECT_FALSE(s.isMemberVisible(5));
    // Showing one of them again resolves the cluster into its members in the session.
    s.setMemberVisible(5, true);
    EXPECT_TRUE(model.state().hiddenClusters.empty());
    EXPECT_EQ(model.state().hiddenMembers, (std::vector<int>{1, 3}));
}

TEST(MemberSelection, OtherMembersStartWithNothingHiddenOrSelectedInTheSession) {
    session::SessionModel model;
    MemberSelection s(&model);
    test::loadTwoGroups(s);
    s.setMemberVisible(2, false);
    s.setSelection({0});
    workbench::MemberFigures others;
    others.names = QStringList{"a", "b", "c"};
    s.setMembers(others);
    EXPECT_TRUE(model.state().hiddenMembers.empty());
    EXPECT_TRUE(model.state().selection.empty());
    EXPECT_TRUE(s.isMemberVisible(2));
    EXPECT_EQ(s.selectedCount(), 0);
}

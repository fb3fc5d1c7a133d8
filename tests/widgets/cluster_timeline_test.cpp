// The clusters-over-time strip: bars sized by their members, clicks selecting a step's
// cluster, hover naming the member under the pointer.
#include "widgets/cluster_timeline.h"

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTest>

#include "panel_fixtures.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {
struct FourMembersOverThreeSteps : ::testing::Test {
    void SetUp() override {
        selection.setMembers(test::figuresOnALine({0.0, 1.0, 2.0, 3.0}));
        strip.resize(400, 200);
        strip.setSteps({"t0", "t1", "t2"});
        // Member 1 leaves cluster 0 for cluster 1 at the second step; the third is not built.
        strip.setStepClusters(0, {0, 0, 1, 1});
        strip.setStepClusters(1, {0, 1, 1, 1});
    }
    workbench::MemberSelection selection;
    ui::ClusterTimeline strip{&selection};
};
}  // namespace

TEST_F(FourMembersOverThreeSteps, EachStepsBarsHoldTheirMembersAndGrowWithThem) {
    EXPECT_EQ(strip.membersAt(1, 1), (QList<int>{1, 2, 3}));
    EXPECT_EQ(strip.membersAt(1, 0), (QList<int>{0}));
    const QRectF one = strip.barRect(1, 0), three = strip.barRect(1, 1);
    ASSERT_FALSE(one.isEmpty());
    EXPECT_NEAR(three.height(), 3.0 * one.height(), 0.5);
    EXPECT_FALSE(one.intersects(three)) << "clusters are stacked apart";
    EXPECT_NEAR(strip.barRect(0, 0).height(), strip.barRect(0, 1).height(), 0.5);
    EXPECT_TRUE(strip.barRect(2, 0).isEmpty()) << "a step not built has no bars";
    EXPECT_LT(strip.columnX(0), strip.columnX(1));
    EXPECT_LT(strip.columnX(1), strip.columnX(2));
}

TEST_F(FourMembersOverThreeSteps, AClickOnABarSelectsThatStepsClusterAndHoverNamesAMember) {
    QSignalSpy clicked(&strip, &ui::ClusterTimeline::membersClicked);
    QTest::mouseClick(&strip, Qt::LeftButton, Qt::ShiftModifier,
                      strip.barRect(1, 1).center().toPoint());
    ASSERT_EQ(clicked.size(), 1);
    EXPECT_EQ(clicked.front().at(0).value<QList<int>>(), (QList<int>{1, 2, 3}));
    EXPECT_EQ(clicked.front().at(1).value<Qt::KeyboardModifiers>(), Qt::ShiftModifier);
    // The same cluster one step earlier held other members.
    QTest::mouseClick(&strip, Qt::LeftButton, Qt::NoModifier,
                      strip.barRect(0, 1).center().toPoint());
    EXPECT_EQ(clicked.back().at(0).value<QList<int>>(), (QList<int>{2, 3}));
    // Member 0 alone in cluster 0 at step 1: the pointer on its bar hovers it.
    QMouseEvent move(QEvent::MouseMove, strip.barRect(1, 0).center(),
                     strip.mapToGlobal(strip.barRect(1, 0).center()), Qt::NoButton, Qt::NoButton,
                     Qt::NoModifier);
    QApplication::sendEvent(&strip, &move);
    EXPECT_EQ(selection.hovered(), 0);
}

// The isovalue controller without a window: on a QCoreApplication, its surfaces go to a display
// that records what it was told, and its members and clusters to the shared selection. What the
// 3D view then draws is the window's business (tests/app).
#include "workbench/isovalue_session.h"

#include <gtest/gtest.h>

#include <QEventLoop>
#include <QSignalSpy>
#include <QTimer>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "data/demo_ensemble.h"
#include "preprocessing/ensemble_moments.h"
#include "session/session_state.h"
#include "tests/support/temp_dir.h"
#include "tests/workbench/recording_display.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {
struct SmallDemo {
    std::shared_ptr<const data::Ensemble> ensemble;
    std::shared_ptr<const prep::EnsembleMoments> moments;
};

SmallDemo smallDemo(std::size_t members) {
    auto demo =
        data::makeDemoEnsemble({.members = members, .nx = 40, .ny = 20, .nz = 8, .seed = 3});
    auto ensemble = std::make_shared<const data::Ensemble>(std::move(demo.ensemble));
    auto moments =
        std::make_shared<const prep::EnsembleMoments>(prep::computeEnsembleMoments(*ensemble));
    return {ensemble, moments};
}

constexpr int kWaitMs = 60000;  // an upper bound for a loaded CI machine, not a pace

// A controller with its display, selection and a cache of its own, as the workbench has them.
class IsovalueSessionTest : public ::testing::Test {
protected:
    // Gives the controller a small demo of `members` members.
    void load(std::size_t members) {
        const SmallDemo demo = smallDemo(members);
        session.setEnsemble(demo.ensemble, demo.moments, "demo-" + std::to_string(members));
    }

    const test::TempDir cache;
    test::RecordingDisplay display;
    workbench::MemberSelection selection;
    workbench::IsovalueSession session{&display, &selection, QString::fromStdString(cache.path())};
};

}  // namespace

TEST_F(IsovalueSessionTest, ShowsTheSurfacesAndGivesTheMembersTheirClustersWithoutAWindow) {
    load(6);
    // The members are known at once, clustered as the workbench opens data (about half of 6).
    ASSERT_EQ(selection.memberCount(), 6);
    EXPECT_EQ(selection.requestedClusterCount(), session::defaultClusters(6));
    EXPECT_EQ(display.surfaces(), nullptr);

    QSignalSpy finished(&session, &workbench::IsovalueSession::finished);
    session.setIsovalue(30.0F, 1.0F);
    EXPECT_TRUE(session.isRunning());
    ASSERT_TRUE(finished.wait(kWaitMs));
    ASSERT_NE(display.surfaces(), nullptr);
    EXPECT_EQ(display.surfaces(), session.result()->meshes);
    EXPECT_FLOAT_EQ(display.surfaces()->isovalue, 30.0F);
    EXPECT_TRUE(finished.front().front().toString().startsWith(QStringLiteral("Isovalue 30")));
    // Every member got its cluster from the result's merge tree, and its figures.
    EXPECT_TRUE(selection.isClustered());
    EXPECT_EQ(selection.clusterCount(), 3);
    EXPECT_EQ(selection.labels().size(), 6U);
    EXPECT_EQ(session.labels(), selection.labels());
    EXPECT_GE(selection.medianMember(), 0);
    // Its reduced-detail copies follow after the first frame, for frames in motion.
    // (their build has no signal of its own: the loop runs until the display is given them)
    if (!display.motion()) {
        QEventLoop loop;
        display.motionArrived = [&loop] { loop.quit(); };
        QTimer::singleShot(kWaitMs, &loop, &QEventLoop::quit);
        loop.exec();
        display.motionArrived = nullptr;
    }
    ASSERT_NE(display.motion(), nullptr);
    EXPECT_EQ(display.motion()->members.size(), display.surfaces()->members.size());

    // Another cluster count changes the selection at once, from the kept distances.
    session.setClusterCount(2);
    EXPECT_EQ(selection.clusterCount(), 2);
    EXPECT_EQ(display.interactions, 0);
}

TEST_F(IsovalueSessionTest, ANewerIsovalueReplacesAnOlderOneStillBeingBuilt) {
    load(4);
    QSignalSpy finished(&session, &workbench::IsovalueSession::finished);
    session.setIsovalue(25.0F, 1.0F);
    session.setIsovalue(35.0F, 1.0F);
    ASSERT_TRUE(finished.wait(kWaitMs));
    // Drain what is left: the older result never reaches the display.
    while (session.isRunning()) ASSERT_TRUE(finished.wait(kWaitMs));
    ASSERT_NE(display.surfaces(), nullptr);
    EXPECT_FLOAT_EQ(display.surfaces()->isovalue, 35.0F);
    for (const auto& summary : finished) {
        EXPECT_FALSE(summary.front().toString().startsWith(QStringLiteral("Isovalue 25")));
    }
}

TEST_F(IsovalueSessionTest, AScrubShowsPreviewsAsMotionAndItsReleaseEndsOnTheFullSurfaces) {
    load(4);
    QSignalSpy finished(&session, &workbench::IsovalueSession::finished);
    session.setIsovalue(30.0F, 1.0F);
    ASSERT_TRUE(finished.wait(kWaitMs));
    const auto full = display.surfaces();

    QSignalSpy previews(&session, &workbench::IsovalueSession::previewShown);
    session.previewIsovalue(32.0F, 1.0F);
    EXPECT_EQ(display.interactions, 1) << "a scrub is drawn as motion";
    ASSERT_TRUE(previews.wait(kWaitMs));
    EXPECT_NE(display.surfaces(), full);
    EXPECT_FLOAT_EQ(previews.front().front().toFloat(), 32.0F);
    // Released where it started: the full surfaces come back, and the motion ends.
    session.endPreview();
    EXPECT_EQ(display.interactions, 0);
    EXPECT_EQ(display.surfaces(), full);
}

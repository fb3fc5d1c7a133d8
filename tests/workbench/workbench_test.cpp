// The workbench's document without a window: opening data and projects on a QCoreApplication,
// what it says when they cannot be opened, and the session it gives new data. What the window
// shows of it is tests/app's business.
#include "workbench/workbench.h"

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QString>
#include <QUndoStack>
#include <vector>

#include "data/demo_ensemble.h"
#include "session/session_history.h"
#include "session/session_model.h"
#include "session/session_state.h"
#include "tests/support/temp_dir.h"
#include "tests/workbench/recording_display.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {

constexpr int kOpeningWaitMs = 60000;  // an upper bound for a loaded CI machine, not a pace
const data::DemoEnsembleParams kSmallDemo{.members = 6, .nx = 32, .ny = 16, .nz = 6, .seed = 5};

class WorkbenchTest : public ::testing::Test {
protected:
    // Opens the small demo and waits for it.
    void openDemo() {
        QSignalSpy arrived(&bench, &workbench::Workbench::dataArrived);
        bench.loadDemo(kSmallDemo);
        ASSERT_TRUE(arrived.wait(kOpeningWaitMs)) << "the demo did not arrive";
    }

    const test::TempDir cache;
    test::RecordingDisplay display;
    workbench::Workbench bench{&display, QString::fromStdString(cache.path().string())};
};

TEST_F(WorkbenchTest, NewDataGetTheShownIsovalueAndTheDefaultClusters) {
    openDemo();
    ASSERT_NE(bench.overview(), nullptr);
    EXPECT_EQ(bench.overview()->ensemble->memberCount(), kSmallDemo.members);
    EXPECT_FALSE(bench.files().has_value()) << "the demo has no files";
    bench.startSessionOfNewData(12.5F);
    const session::SessionState& s = bench.model()->state();
    EXPECT_TRUE(s.demo);
    EXPECT_EQ(s.demoParams.members, kSmallDemo.members);
    ASSERT_TRUE(s.isovalue.has_value());
    EXPECT_FLOAT_EQ(*s.isovalue, 12.5F);
    EXPECT_EQ(s.clusters, session::defaultClusters(static_cast<int>(kSmallDemo.members)));
}

// Undo takes back the user's edits of these data, and the window is asked to place the camera
// of the step; new data's first surfaces start the history afresh.
TEST_F(WorkbenchTest, UndoAppliesTheSessionBeforeAndNewDataStartTheHistoryAfresh) {
    const auto showNewData = [this] {
        bench.startSessionOfNewData(bench.overview()->defaultIsovalue);
        QSignalSpy built(bench.isovalue(), &workbench::IsovalueSession::finished);
        bench.buildFirstSurfaces();
        ASSERT_TRUE(built.wait(kOpeningWaitMs));
        bench.surfacesShown();
    };
    openDemo();
    showNewData();
    QUndoStack& steps = *bench.history()->stack();
    EXPECT_FALSE(steps.canUndo());
    const int clusters = bench.model()->state().clusters;
    bench.model()->update([](session::SessionState& s) { s.clusters = 4; });
    bench.history()->record();
    ASSERT_TRUE(steps.canUndo());

    QSignalSpy applied(&bench, &workbench::Workbench::sessionApplied);
    steps.undo();
    EXPECT_EQ(bench.model()->state().clusters, clusters);
    ASSERT_EQ(applied.size(), 1) << "the window places the step's camera";
    steps.redo();
    EXPECT_EQ(bench.model()->state().clusters, 4);

    openDemo();
    EXPECT_TRUE(steps.canUndo()) << "until the new data's surfaces are shown";
    showNewData();
    EXPECT_FALSE(steps.canUndo()) << "the old data's edits cannot be undone on the new data";
}

TEST_F(WorkbenchTest, AFileThatCannotBeReadIsNamedAndTheDataOnScreenStay) {
    openDemo();
    const engine::EnsembleOverview* shown = bench.overview();
    QSignalSpy failed(&bench, &workbench::Workbench::openingFailed);
    data::DataSelection missing;
    missing.paths = {(cache.path() / "no_such_members.nc").string()};
    bench.openFiles(missing);
    ASSERT_TRUE(failed.wait(kOpeningWaitMs));
    EXPECT_TRUE(failed.front().front().toString().contains("no_such_members.nc"))
        << failed.front().front().toString().toStdString();
    EXPECT_EQ(bench.overview(), shown) << "the demo stays on screen";
}

TEST_F(WorkbenchTest, AFileWithoutAMemberDimensionAsksWhichDimensionStandsIn) {
    QSignalSpy asked(&bench, &workbench::Workbench::memberDimensionAsked);
    QSignalSpy failed(&bench, &workbench::Workbench::openingFailed);
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/contour.cdf"};
    selection.variable = "T";
    bench.openFiles(selection);
    ASSERT_TRUE(asked.wait(kOpeningWaitMs));
    EXPECT_EQ(asked.front().at(0).toString(), QStringLiteral("contour.cdf"));
    EXPECT_EQ(asked.front().at(1).toStringList(), QStringList{QStringLiteral("frtime")});
    EXPECT_TRUE(failed.isEmpty()) << "a question, not a failure";

    QSignalSpy arrived(&bench, &workbench::Workbench::dataArrived);
    selection.memberDimension = "frtime";
    bench.openFiles(selection);
    ASSERT_TRUE(arrived.wait(kOpeningWaitMs));
    EXPECT_EQ(bench.overview()->ensemble->memberCount(), 7U);
}

TEST_F(WorkbenchTest, CancellingKeepsWhatIsOnScreen) {
    QSignalSpy cancelled(&bench, &workbench::Workbench::openingCancelled);
    QSignalSpy arrived(&bench, &workbench::Workbench::dataArrived);
    bench.loadDemo(kSmallDemo);
    bench.cancel();  // before the job's end is seen: its result is dropped
    ASSERT_TRUE(cancelled.wait(kOpeningWaitMs));
    EXPECT_TRUE(arrived.isEmpty());
    EXPECT_EQ(bench.overview(), nullptr);
}

// A project's session comes with its data, its members' visibility and selection once their
// clusters are known, and only then is it the project on screen.
TEST_F(WorkbenchTest, AProjectIsAppliedWhenItsDataArriveAndItsMembersOnceClustered) {
    openDemo();  // for an isovalue of its values other than the opening one
    const float isovalue = bench.overview()->defaultIsovalue * 1.05F;
    session::SessionState project;
    project.demo = true;
    project.demoParams = kSmallDemo;
    project.isovalue = isovalue;
    project.clusters = 2;
    project.hiddenMembers = {1, 4};
    project.selection = {2};
    const QString path = QString::fromStdString((cache.path() / "saved.ensil").string());

    QSignalSpy arrived(&bench, &workbench::Workbench::dataArrived);
    QSignalSpy opened(&bench, &workbench::Workbench::projectOpened);
    bench.openProject(project, path);
    ASSERT_TRUE(arrived.wait(kOpeningWaitMs));
    bench.startSessionOfNewData(bench.overview()->defaultIsovalue);
    const session::SessionState& s = bench.model()->state();
    ASSERT_TRUE(s.isovalue.has_value());
    EXPECT_FLOAT_EQ(*s.isovalue, isovalue) << "the project's isovalue, not the opening one";
    EXPECT_EQ(s.clusters, 2);
    EXPECT_TRUE(s.hiddenMembers.empty()) << "members wait for their clusters";
    EXPECT_TRUE(bench.projectPath().isEmpty()) << "not the project on screen yet";
    ASSERT_NE(bench.pendingProject(), nullptr);

    QSignalSpy built(bench.isovalue(), &workbench::IsovalueSession::finished);
    bench.buildFirstSurfaces();
    ASSERT_TRUE(built.wait(kOpeningWaitMs));
    ASSERT_TRUE(bench.selection()->isClustered());
    bench.surfacesShown();
    EXPECT_EQ(s.hiddenMembers, (std::vector<int>{1, 4}));
    EXPECT_EQ(s.selection, (std::vector<int>{2}));
    ASSERT_EQ(opened.size(), 1);
    EXPECT_EQ(opened.front().front().toString(), path);
    EXPECT_EQ(bench.projectPath(), path);
    EXPECT_EQ(bench.pendingProject(), nullptr);
}

TEST_F(WorkbenchTest, AProjectWhoseDataCannotBeReadIsDropped) {
    session::SessionState project;
    project.data.paths = {(cache.path() / "moved_away.nc").string()};
    project.isovalue = 1.0F;
    QSignalSpy failed(&bench, &workbench::Workbench::openingFailed);
    bench.openProject(project, QString::fromStdString((cache.path() / "p.ensil").string()));
    ASSERT_TRUE(failed.wait(kOpeningWaitMs));
    EXPECT_EQ(bench.pendingProject(), nullptr)
        << "a project left pending would be applied to the next data opened";

    openDemo();
    bench.startSessionOfNewData(3.0F);
    EXPECT_FLOAT_EQ(*bench.model()->state().isovalue, 3.0F);
    EXPECT_TRUE(bench.projectPath().isEmpty());
}

}  // namespace

// Stepping through time without a window: a step is read while the step shown stays, arrives
// with its data and then its surfaces; a step visited before comes back without reading; the
// next step is read ahead in the direction of the last move.
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTest>
#include <string>

#include "session/session_model.h"
#include "tests/support/temp_dir.h"
#include "tests/workbench/opened_steps.h"
#include "tests/workbench/recording_display.h"
#include "workbench/isovalue_session.h"
#include "workbench/time_steps.h"
#include "workbench/workbench.h"

using namespace ensil;

namespace {

class WorkbenchTimeTest : public ::testing::Test {
protected:
    // Goes to the step and waits until its surfaces are built.
    void goTo(std::size_t step) {
        QSignalSpy built(bench.isovalue(), &workbench::IsovalueSession::finished);
        bench.model()->update([step](session::SessionState& s) { s.data.timeIndex = step; });
        bench.goToStep(step);
        ASSERT_TRUE(QTest::qWaitFor(
            [&] { return bench.shownStep() == step && !bench.isovalue()->isRunning(); },
            test::kStepWaitMs));
    }

    const test::TempDir dir;
    test::RecordingDisplay display;
    workbench::Workbench bench{&display, QString::fromStdString(dir.path().string())};
};

TEST_F(WorkbenchTimeTest, AStepIsReadWhileTheStepShownStaysThenArrivesWithItsSurfaces) {
    ASSERT_NO_FATAL_FAILURE(test::openDemoSteps(bench, dir.file("steps.nc")));
    const engine::EnsembleOverview* first = bench.overview();
    const auto firstValues = first->ensemble->members[0].values;
    const auto firstSurfaces = display.surfaces();
    ASSERT_NE(firstSurfaces, nullptr);
    QSignalSpy reading(&bench, &workbench::Workbench::stepReading);
    QSignalSpy arrived(&bench, &workbench::Workbench::stepArrived);
    bench.model()->update([](session::SessionState& s) { s.data.timeIndex = 1; });
    bench.goToStep(1);
    ASSERT_EQ(reading.size(), 1);
    EXPECT_EQ(bench.overview(), first) << "step 0 stays on screen while step 1 is read";
    EXPECT_EQ(display.surfaces(), firstSurfaces);
    ASSERT_TRUE(arrived.wait(test::kStepWaitMs));
    EXPECT_EQ(bench.shownStep(), 1U);
    EXPECT_NE(bench.overview()->ensemble->members[0].values, firstValues) << "step 1's data";
    QSignalSpy built(bench.isovalue(), &workbench::IsovalueSession::finished);
    ASSERT_TRUE(built.wait(test::kStepWaitMs)) << "the arrived step's surfaces are built";
    EXPECT_NE(display.surfaces(), firstSurfaces);
}

TEST_F(WorkbenchTimeTest, AStepVisitedBeforeComesBackWithoutReading) {
    ASSERT_NO_FATAL_FAILURE(test::openDemoSteps(bench, dir.file("steps.nc")));
    const auto firstSurfaces = display.surfaces();
    ASSERT_NO_FATAL_FAILURE(goTo(1));
    QSignalSpy reading(&bench, &workbench::Workbench::stepReading);
    QSignalSpy arrived(&bench, &workbench::Workbench::stepArrived);
    bench.model()->update([](session::SessionState& s) { s.data.timeIndex = 0; });
    bench.goToStep(0);
    EXPECT_TRUE(reading.isEmpty()) << "kept from the visit before";
    EXPECT_EQ(arrived.size(), 1) << "at once, in this event";
    EXPECT_EQ(bench.shownStep(), 0U);
    EXPECT_EQ(display.surfaces(), firstSurfaces) << "its surfaces kept too";
}

TEST_F(WorkbenchTimeTest, TheNextStepIsReadAheadInTheDirectionOfTheLastMove) {
    ASSERT_NO_FATAL_FAILURE(test::openDemoSteps(bench, dir.file("steps.nc")));
    ASSERT_NO_FATAL_FAILURE(goTo(1));
    QSignalSpy read(bench.timeSteps(), &workbench::TimeSteps::stepRead);
    bench.readAhead(/*playing=*/false);
    ASSERT_TRUE(read.wait(test::kStepWaitMs));
    EXPECT_EQ(read.front().front().value<std::size_t>(), 2U) << "forward, as the last move";
    QSignalSpy reading(&bench, &workbench::Workbench::stepReading);
    QSignalSpy arrived(&bench, &workbench::Workbench::stepArrived);
    bench.model()->update([](session::SessionState& s) { s.data.timeIndex = 2; });
    bench.goToStep(2);
    EXPECT_TRUE(reading.isEmpty()) << "read ahead: shown without reading";
    EXPECT_EQ(arrived.size(), 1);
}

}  // namespace

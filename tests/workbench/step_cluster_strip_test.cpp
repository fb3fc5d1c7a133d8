// Every time step's clusters without a window: the step shown gives its own, the others are
// clustered in the background as the command line clusters them (engine::clusterTimeStep), and
// clustering the steps otherwise starts the strip again.
#include "workbench/step_cluster_strip.h"

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTest>
#include <string>
#include <vector>

#include "engine/time_series.h"
#include "session/session_model.h"
#include "tests/support/temp_dir.h"
#include "tests/workbench/opened_steps.h"
#include "tests/workbench/recording_display.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"
#include "workbench/workbench.h"

using namespace ensil;

namespace {

class StepClusterStripTest : public ::testing::Test {
protected:
    // Opens the demo over three steps and shows step 0's surfaces, as the window does.
    void openSteps() {
        ASSERT_NO_FATAL_FAILURE(test::openDemoSteps(bench, path));
        strip.stepBuilt();
        strip.recordShown();
    }
    [[nodiscard]] bool everyStepClustered() const {
        return QTest::qWaitFor(
            [this] {
                for (int s = 0; s < strip.stepCount(); ++s) {
                    if (strip.stepClusters(s).empty()) return false;
                }
                return !strip.stepClusters(0).empty();
            },
            test::kStepWaitMs);
    }
    // The step's clusters as the command line gives them, matched to step 0's.
    [[nodiscard]] std::vector<int> commandLineClusters(int step) const {
        const session::SessionState& s = bench.model()->state();
        engine::StepClusteringRequest request;
        request.selection = bench.timeStepSelection(static_cast<std::size_t>(step));
        request.isovalue = *s.isovalue;
        request.k = bench.selection()->clusterCount();
        request.linkage = s.linkage;
        for (int m = 0; m < bench.selection()->memberCount(); ++m) {
            request.previousMembers.push_back(bench.selection()->name(m).toStdString());
        }
        request.previousIdentities = strip.stepClusters(step - 1);
        const engine::StepClusters clusters = engine::clusterTimeStep(request, {}, {});
        return engine::previousIdentitiesByName(clusters.members, clusters.memberIdentities,
                                                request.previousMembers);
    }

    const test::TempDir dir;
    const std::string path = dir.file("steps.nc");
    test::RecordingDisplay display;
    workbench::Workbench bench{&display, QString::fromStdString(dir.path().string())};
    workbench::StepClusterStrip& strip = *bench.strip();
};

TEST_F(StepClusterStripTest, TheStepsNotVisitedAreClusteredAsTheCommandLineClustersThem) {
    ASSERT_NO_FATAL_FAILURE(openSteps());
    ASSERT_EQ(strip.stepCount(), static_cast<int>(test::kDemoSteps));
    ASSERT_TRUE(everyStepClustered());
    for (int step = 1; step < static_cast<int>(test::kDemoSteps); ++step) {
        EXPECT_EQ(strip.stepClusters(step), commandLineClusters(step)) << "step " << step;
    }
}

TEST_F(StepClusterStripTest, AnotherClusterCountStartsTheStripAgain) {
    ASSERT_NO_FATAL_FAILURE(openSteps());
    ASSERT_TRUE(everyStepClustered());
    QSignalSpy changed(&strip, &workbench::StepClusterStrip::stepsChanged);
    const int k = bench.selection()->clusterCount() == 2 ? 3 : 2;
    bench.model()->update([k](session::SessionState& s) { s.clusters = k; });
    bench.selection()->setClusterCount(k);  // as the window's bindings do
    ASSERT_GE(changed.size(), 1) << "steps clustered at another k are not comparable";
    ASSERT_TRUE(everyStepClustered());
    for (int step = 1; step < static_cast<int>(test::kDemoSteps); ++step) {
        EXPECT_EQ(strip.stepClusters(step), commandLineClusters(step)) << "step " << step;
    }
}

TEST_F(StepClusterStripTest, StoppedFillingLeavesTheOtherStepsUnclustered) {
    ASSERT_NO_FATAL_FAILURE(openSteps());  // step 0 recorded, step 1's clustering started
    ASSERT_FALSE(strip.stepClusters(0).empty());
    QSignalSpy filling(&strip, &workbench::StepClusterStrip::fillingChanged);
    strip.stopFilling();
    ASSERT_EQ(filling.size(), 1);
    // The cancelled job's end asks for the next step, which a stopped strip does not start.
    ASSERT_TRUE(filling.wait(test::kStepWaitMs));
    EXPECT_EQ(filling.back().at(1).toInt(), 0) << "filling is not said to go on";
    EXPECT_TRUE(strip.stepClusters(1).empty());
    EXPECT_TRUE(strip.stepClusters(2).empty());
}

}  // namespace

// The workbench on an ensemble larger than its memory budget (issue 20): it opens a thinned copy
// read in slabs instead of refusing, says so, shows the surfaces and clusters the whole data
// give (equal to the in-memory job's), and fills the cluster-over-time strip from slab passes
// as the command line clusters the steps in memory.
#include <gtest/gtest.h>

#include <QDockWidget>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>

#include "app/main_window.h"
#include "data/demo_ensemble.h"
#include "data/netcdf_writer.h"
#include "engine/isovalue_job.h"
#include "engine/streaming_run.h"
#include "engine/time_series.h"
#include "tests/app/workbench_helpers.h"
#include "tests/streaming/same_results.h"
#include "tests/support/scoped_cache_home.h"
#include "tests/support/temp_dir.h"
#include "widgets/cluster_timeline.h"
#include "widgets/ensemble_info_panel.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {

constexpr data::DemoEnsembleParams kDemo{.members = 24, .nx = 97, .ny = 96, .nz = 25};
constexpr std::size_t kSteps = 3;

// The demo over three steps (members change groups), as NetCDF.
std::string writeSteps(const test::TempDir& dir) {
    const std::string path = dir.file("steps.nc");
    data::writeNetcdfSteps(
        [](std::size_t step) { return data::makeDemoEnsembleAt(kDemo, step, kSteps).ensemble; },
        {data::kDemoTimeUnits, {0.0, 12.0, 24.0}}, path);
    return path;
}

}  // namespace

TEST(MainWindowStreaming, OpensDataLargerThanItsBudgetInSlabsWithTheInMemorySurfaces) {
    const test::ScopedCacheHome cache;
    test::TempDir dir;
    const data::DataSelection selection{.paths = {writeSteps(dir)}};
    const data::EnsembleDescription d = data::describeEnsemble(selection);
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1200, 800}));
    window.setMemoryLimit(engine::inMemoryPeakBytes(d) - 1);
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    QSignalSpy failed(&window, &app::MainWindow::loadingFailed);
    window.openFiles(selection);
    ASSERT_TRUE(built.wait(280000))
        << "failed: "
        << (failed.isEmpty() ? QString() : failed.front().front().toString()).toStdString();

    // Said in the info panel.
    ASSERT_NE(window.overview(), nullptr);
    ASSERT_TRUE(window.overview()->streamed);
    EXPECT_EQ(window.overview()->streamed->stride, 2u);
    EXPECT_TRUE(window.infoPanel()->text().contains(
        QStringLiteral("larger than the workbench's memory budget")))
        << window.infoPanel()->text().toStdString();
    EXPECT_TRUE(window.infoPanel()->text().contains(QStringLiteral("97 x 96 x 25")))
        << "the whole data's grid";

    // For the eye: the info panel's facts and note beside the view (see the closing note).
    for (QWidget* w = window.infoPanel(); w != nullptr; w = w->parentWidget()) {
        if (auto* dock = qobject_cast<QDockWidget*>(w)) dock->raise();
        if (auto* scroll = qobject_cast<QScrollArea*>(w)) {
            scroll->verticalScrollBar()->setValue(scroll->verticalScrollBar()->maximum());
        }
    }
    window.grab().save(QStringLiteral(ENSIL_TEST_OUTPUT_DIR "/streamed_workbench.png"));

    // The surfaces and distances are the whole data's.
    const session::SessionState state = window.captureSession();
    const auto whole = std::make_shared<const data::Ensemble>(data::openEnsemble(selection));
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(*whole);
    engine::IsovalueJobInput input;
    input.ensemble = whole.get();
    input.moments = &moments;
    input.options.isovalue = *state.isovalue;
    input.verticalExaggeration = state.verticalExaggeration;
    const engine::IsovalueOutcome want = engine::runIsovalueJob(input);
    const workbench::IsovalueResult& got = *window.isovalueSession()->result();
    ASSERT_EQ(got.meshes->members.size(), want.meshes.members.size());
    for (std::size_t m = 0; m < want.meshes.members.size(); ++m) {
        EXPECT_TRUE(test::sameMesh(got.meshes->members[m], want.meshes.members[m]))
            << "member " << m;
    }
    test::expectSameDistances(got.distances, want.distances);
    test::expectSameTree(got.tree, want.tree);

    // The strip gets every step's clusters from slab passes, as they are clustered with the
    // step in memory.
    const ui::ClusterTimeline& strip = *window.findChild<ui::ClusterTimeline*>();
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            for (int s = 0; s < static_cast<int>(kSteps); ++s) {
                if (strip.stepClusters(s).size() != kDemo.members) return false;
            }
            return !strip.fillingButton()->isVisible();
        },
        280000));
    // Each step matched to the one before it, as the strip matches them (in memory here).
    for (std::size_t s = 1; s < kSteps; ++s) {
        engine::StepClusteringRequest request;
        request.selection = selection;
        request.selection.timeIndex = s;
        request.isovalue = *state.isovalue;
        request.k = window.memberSelection()->clusterCount();
        for (int m = 0; m < window.memberSelection()->memberCount(); ++m) {
            request.previousMembers.push_back(window.memberSelection()->name(m).toStdString());
        }
        request.previousIdentities = strip.stepClusters(static_cast<int>(s) - 1);
        const engine::StepClusters inMemory = engine::clusterTimeStep(request, {});
        EXPECT_EQ(strip.stepClusters(static_cast<int>(s)), inMemory.memberIdentities)
            << "step " << s;
    }
}

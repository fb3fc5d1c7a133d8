// Time as an axis of the workbench session: the time bar steps ERA5 through its four times,
// each step's surfaces replacing the last only when built, clusters keeping their colours,
// the strip recording each step, undo going back a step, and a project keeping the step.
#include <gtest/gtest.h>

#include <QAction>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>
#include <QToolButton>

#include "app/main_window.h"
#include "data/demo_ensemble.h"
#include "data/netcdf_writer.h"
#include "engine/isovalue_job.h"
#include "engine/time_series.h"
#include "tests/app/held_job_threads.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/scoped_cache_home.h"
#include "tests/support/temp_dir.h"
#include "widgets/cluster_timeline.h"
#include "widgets/member_table_model.h"
#include "widgets/member_table_panel.h"
#include "widgets/silhouette_view.h"
#include "widgets/time_bar.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {
// Writes the demo over two steps, 12 hours apart, into `dir`; returns the file's path.
std::string writeTwoDemoSteps(const test::TempDir& dir, const data::DemoEnsembleParams& demo) {
    const std::string path = dir.file("steps.nc");
    data::writeNetcdfSteps(
        [&](std::size_t step) { return data::makeDemoEnsembleAt(demo, step, 2).ensemble; },
        {data::kDemoTimeUnits, {0.0, 12.0}}, path);
    return path;
}

// Waits until the step's surfaces are on screen.
bool stepShown(app::MainWindow& window, int step) {
    return QTest::qWaitFor(
        [&] {
            return window.timeBar()->shownStep() == step && window.timeBar()->pendingStep() < 0 &&
                   !window.isovalueSession()->isRunning();
        },
        60000);
}
// Shows the workbench and opens ERA5's variable (the NetCDF file, or its GRIB twin), waiting
// for its first surfaces.
bool openEra5(app::MainWindow& window, QSize size, const char* variable,
              const char* file = "era5_eda_members.nc") {
    if (!test::showWorkbench(window, size)) return false;
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    data::DataSelection selection;
    selection.paths = {std::string(ENSIL_SHARED_DATA_DIR "/") + file};
    selection.variable = variable;
    window.openFiles(selection);
    // Under ASan, beside another test and a window still working in the background, the GRIB
    // twin's first surfaces once took longer than 60 s.
    return built.wait(120000);
}
}  // namespace

TEST(MainWindowTime, TheTimeBarStepsThroughEra5sTimesKeepingTheLastPictureUntilTheNextIsBuilt) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(openEra5(window, {1000, 700}, "t"));
    ui::TimeBar& bar = *window.timeBar();
    ASSERT_EQ(bar.stepCount(), 4);
    EXPECT_EQ(bar.shownStep(), 0);
    const gl::Renderer& renderer = window.view()->renderer();
    const auto firstMeshes = renderer.meshes();
    const float firstValue = window.overview()->ensemble->members[0].values[0];
    EXPECT_TRUE(renderer.title().contains("2017-01-01T00:00")) << renderer.title().toStdString();

    // Until step 1 is built, step 0's surfaces stay on screen: when step 1's surfaces start
    // being built (its data read), step 0's are still there.
    std::shared_ptr<const data::MeshSet> whileBuilding;
    QObject::connect(window.isovalueSession(), &workbench::IsovalueSession::started, &window,
                     [&] { whileBuilding = renderer.meshes(); });
    bar.step(1);
    EXPECT_EQ(bar.pendingStep(), 1);
    ASSERT_TRUE(stepShown(window, 1));
    EXPECT_EQ(whileBuilding, firstMeshes);
    EXPECT_NE(renderer.meshes(), firstMeshes);
    EXPECT_EQ(window.overview()->ensemble->memberCount(), 10u);
    EXPECT_NE(window.overview()->ensemble->members[0].values[0], firstValue) << "another time";
    EXPECT_TRUE(renderer.title().contains("2017-01-01T12:00")) << renderer.title().toStdString();
    EXPECT_EQ(window.captureSession().data.timeIndex, 1u);

    // The strip holds both steps' clusters, each member in one.
    const ui::ClusterTimeline& strip = *window.findChild<ui::ClusterTimeline*>();
    EXPECT_EQ(strip.stepClusters(0).size(), 10u);
    EXPECT_EQ(strip.stepClusters(1).size(), 10u);
    workbench::MemberSelection& members = *window.memberSelection();
    for (int m = 0; m < 10; ++m) {
        EXPECT_EQ(strip.stepClusters(1)[static_cast<std::size_t>(m)],
                  members.identityOf(members.clusterOf(m)));
    }
    // A click on a bar selects that cluster's members at that step.
    const int identity = strip.stepClusters(0).front();
    const QList<int> cluster = strip.membersAt(0, identity);
    QTest::mouseClick(const_cast<ui::ClusterTimeline*>(&strip), Qt::LeftButton, Qt::NoModifier,
                      strip.barRect(0, identity).center().toPoint());
    EXPECT_EQ(members.selectedMembers(), cluster);

    // Undo goes back to the step before.
    QAction* undo = window.findChild<QAction*>("undoAction");
    ASSERT_TRUE(QTest::qWaitFor([&] { return undo->text().contains("Time Step 1 -> 2"); }, 10000))
        << undo->text().toStdString();
    undo->trigger();
    ASSERT_TRUE(stepShown(window, 0));
    EXPECT_EQ(window.overview()->ensemble->members[0].values[0], firstValue);
}

TEST(MainWindowTime, PlayingThroughEra5ShowsEveryStepOnceAndFillsTheStrip) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(openEra5(window, {1400, 900}, "z"));
    ui::TimeBar& bar = *window.timeBar();
    // Each step shown is saved as the workbench shows it (for the eye; see the closing note).
    std::vector<int> shown;
    QObject::connect(window.isovalueSession(), &workbench::IsovalueSession::finished, &window, [&] {
        shown.push_back(bar.shownStep());
        window.grab().save(
            QStringLiteral(ENSIL_TEST_OUTPUT_DIR "/era5_time_step_%1.png").arg(bar.shownStep()));
    });
    bar.setLoop(false);
    bar.setStepsPerSecond(20.0);
    bar.play();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !bar.isPlaying(); }, 120000));
    ASSERT_TRUE(stepShown(window, 3));
    EXPECT_EQ(shown, (std::vector<int>{1, 2, 3})) << "each step once, in order, none skipped";
    const ui::ClusterTimeline& strip = *window.findChild<ui::ClusterTimeline*>();
    for (int s = 0; s < 4; ++s) EXPECT_EQ(strip.stepClusters(s).size(), 10u) << "step " << s;
}

TEST(MainWindowTime, AStepVisitedAgainIsShownAsBuiltBeforeWithoutRebuilding) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(openEra5(window, {1000, 700}, "t"));
    const auto first = window.view()->renderer().meshes();
    window.timeBar()->step(1);
    ASSERT_TRUE(stepShown(window, 1));
    EXPECT_FALSE(window.isovalueSession()->result()->keptInMemory);
    // Shown at once, on the GUI thread: no job to wait for, and no frame of step 1 drawn
    // before step 0's surfaces are on screen.
    int frames = 0;
    QObject::connect(window.view(), &QOpenGLWidget::frameSwapped, &window, [&] { ++frames; });
    QSignalSpy finished(window.isovalueSession(), &workbench::IsovalueSession::finished);
    window.timeBar()->step(-1);
    EXPECT_FALSE(window.isovalueSession()->isRunning()) << "a kept step needs no job";
    EXPECT_EQ(finished.count(), 1) << "its surfaces shown at once, with its floor and title";
    ASSERT_TRUE(finished.count() > 0 || finished.wait(10000));
    EXPECT_EQ(frames, 0) << "no frame of the last step before the kept one is shown";
    // Its first frame is a motion frame (a full software-OpenGL frame of every member takes
    // longer than a step may); the full resolution follows once the steps pause.
    EXPECT_TRUE(window.view()->inMotion());
    ASSERT_TRUE(QTest::qWaitFor([&] { return !window.view()->inMotion(); }, 10000));
    ASSERT_TRUE(stepShown(window, 0));
    EXPECT_TRUE(window.isovalueSession()->result()->keptInMemory);
    EXPECT_EQ(window.view()->renderer().meshes(), first) << "the very surfaces of before";
}

TEST(MainWindowTime, TheNextStepIsReadAndBuiltAheadAndShownAtOnceAsBuiltDirectly) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    QSignalSpy prepared(window.isovalueSession(), &workbench::IsovalueSession::preparationEnded);
    ASSERT_TRUE(openEra5(window, {1000, 700}, "t"));
    // While step 0 is looked at, step 1 is read and its surfaces built in the background.
    ASSERT_TRUE(prepared.count() > 0 || prepared.wait(60000));
    EXPECT_FALSE(window.isovalueSession()->isPreparing());
    EXPECT_EQ(window.timeBar()->shownStep(), 0) << "built ahead, not shown";
    QSignalSpy finished(window.isovalueSession(), &workbench::IsovalueSession::finished);
    window.timeBar()->step(1);
    EXPECT_EQ(finished.count(), 1) << "shown at once, in the request's own event";
    EXPECT_FALSE(window.isovalueSession()->isRunning());
    ASSERT_TRUE(stepShown(window, 1));
    const workbench::IsovalueResult& shown = *window.isovalueSession()->result();
    EXPECT_TRUE(shown.keptInMemory);
    // Built with its motion meshes, which its first frame (a motion frame) draws.
    ASSERT_NE(shown.motionMeshes, nullptr);
    EXPECT_EQ(shown.motionMeshes->members.size(), shown.meshes->members.size());
    EXPECT_EQ(window.view()->renderer().motionMeshes(), shown.motionMeshes);

    // The same surfaces, distances and clusters as built directly for step 1.
    const engine::EnsembleOverview& step = *window.overview();
    engine::IsovalueJobInput input;
    input.ensemble = step.ensemble.get();
    input.moments = step.moments.get();
    input.options.isovalue = shown.meshes->isovalue;
    const engine::IsovalueOutcome direct = engine::runIsovalueJob(input, {}, {});
    EXPECT_EQ(shown.triangles, direct.meshes.triangles);
    ASSERT_EQ(shown.meshes->members.size(), direct.meshes.members.size());
    for (std::size_t m = 0; m < direct.meshes.members.size(); ++m) {
        EXPECT_EQ(shown.meshes->members[m].indices, direct.meshes.members[m].indices) << m;
    }
    ASSERT_EQ(shown.distances.values.size(), direct.distances.values.size());
    for (std::size_t i = 0; i < direct.distances.values.size(); ++i) {
        EXPECT_DOUBLE_EQ(shown.distances.values[i], direct.distances.values[i]) << i;
    }
    EXPECT_EQ(shown.depth, direct.boxplot.depth);

    // Step 1 shown, step 2 (the way the user went) is read and built ahead in its turn.
    ASSERT_TRUE(QTest::qWaitFor([&] { return prepared.count() >= 2; }, 60000));
    window.timeBar()->step(1);
    ASSERT_TRUE(stepShown(window, 2));
    EXPECT_TRUE(window.isovalueSession()->result()->keptInMemory);
}

TEST(MainWindowTime, AStepAskedForWhileBuiltAheadWaitsForThatBuild) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(openEra5(window, {1000, 700}, "t"));
    workbench::IsovalueSession& session = *window.isovalueSession();
    const engine::EnsembleOverview& shown = *window.overview();
    const float iso = session.result()->meshes->isovalue;
    // Another step's data (the same values under another key), prepared and then asked for
    // before the preparation can have ended (its result needs this thread's events).
    session.prepareTimeStep(shown.ensemble, shown.moments, "another step", iso, 1.0F);
    ASSERT_TRUE(session.isPreparing());
    QSignalSpy finished(&session, &workbench::IsovalueSession::finished);
    QSignalSpy failed(&session, &workbench::IsovalueSession::failed);
    session.setTimeStep(shown.ensemble, shown.moments, "another step");
    session.setIsovalue(iso, 1.0F);
    EXPECT_TRUE(session.awaitsPreparedStep()) << "no second build of the same surfaces";
    EXPECT_TRUE(session.isRunning());
    ASSERT_TRUE(finished.wait(60000));
    EXPECT_EQ(failed.count(), 0) << "the job given up for it says nothing";
    EXPECT_FALSE(session.awaitsPreparedStep());
    EXPECT_FALSE(session.isRunning());
    EXPECT_FALSE(session.result()->keptInMemory);
    EXPECT_EQ(session.result()->meshes->isovalue, iso);
    // Kept as well: asked for again, shown at once.
    EXPECT_TRUE(session.showKept(iso, 1.0F));
    EXPECT_TRUE(session.result()->keptInMemory);
}

TEST(MainWindowTime, AStepNeverSeenIsPreviewedInReducedDetailUntilItsFullSurfaces) {
    const test::ScopedCacheHome cache;
    test::TempDir dir;
    // The demo over two steps, large enough that its full surfaces take many times a preview's.
    constexpr data::DemoEnsembleParams kDemo{.members = 24, .nx = 97, .ny = 96, .nz = 25};
    const std::string path = writeTwoDemoSteps(dir, kDemo);
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1000, 700}));
    workbench::IsovalueSession& session = *window.isovalueSession();
    QSignalSpy built(&session, &workbench::IsovalueSession::finished);
    window.openFiles(data::DataSelection{.paths = {path}});
    ASSERT_TRUE(built.wait(120000));
    const auto first = window.view()->renderer().meshes();

    // Asked for at once (its reading ahead just begun): read, then built, with a preview. The
    // jobs' threads are held until the preview is shown, so that the full build cannot end
    // first, as it may on a busy machine (the preview has a thread of its own; the full
    // surfaces are then shown without it, and this test saw {full}).
    // From when the jobs already running (the reading ahead among them) have ended, which under
    // ASan beside other work took longer than 30 s once. (The GUI thread waits, so nothing new
    // starts meanwhile.)
    test::HeldJobThreads jobThreads(120000);
    ASSERT_TRUE(jobThreads.held());
    std::vector<std::string> order;
    std::shared_ptr<const data::MeshSet> previewed;
    QObject::connect(&session, &workbench::IsovalueSession::previewShown, &window, [&] {
        order.emplace_back("preview");
        previewed = window.view()->renderer().meshes();
        EXPECT_TRUE(window.view()->inMotion()) << "a preview is drawn as motion frames";
        jobThreads.release();
    });
    std::shared_ptr<const data::MeshSet> motionAtFirstFrame;
    QObject::connect(&session, &workbench::IsovalueSession::finished, &window, [&] {
        order.emplace_back("full");
        motionAtFirstFrame = window.view()->renderer().motionMeshes();
    });
    window.timeBar()->step(1);
    ASSERT_TRUE(stepShown(window, 1));
    ASSERT_EQ(order, (std::vector<std::string>{"preview", "full"}));
    ASSERT_NE(previewed, nullptr);
    EXPECT_NE(previewed, first) << "the preview is step 1's";
    EXPECT_EQ(previewed->members.size(), kDemo.members);
    const workbench::IsovalueResult& full = *session.result();
    EXPECT_FALSE(full.keptInMemory);
    const auto indices = [](const data::MeshSet& set) {
        std::size_t n = 0;
        for (const data::PackedMesh& m : set.members) n += m.indices.size();
        return n;
    };
    EXPECT_LT(indices(*previewed), indices(*full.meshes)) << "reduced detail";
    EXPECT_EQ(window.view()->renderer().meshes(), full.meshes) << "the full surfaces replace it";
    // Their reduced detail for motion frames is the preview, from their first frame (a motion
    // frame) on, not built again.
    EXPECT_EQ(motionAtFirstFrame, previewed) << "the first motion frame draws the preview";
    EXPECT_EQ(window.view()->renderer().motionMeshes(), previewed);
    EXPECT_EQ(session.result()->motionMeshes, previewed);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !window.view()->inMotion(); }, 10000))
        << "the view settles at full resolution";
}

// Waits until the strip holds each of ERA5's four steps' clusters.
bool stripFilled(const app::MainWindow& window) {
    const ui::ClusterTimeline& strip = *window.findChild<ui::ClusterTimeline*>();
    return QTest::qWaitFor(
        [&] {
            for (int s = 0; s < 4; ++s) {
                if (strip.stepClusters(s).size() != 10u) return false;
            }
            return !strip.fillingButton()->isVisible();
        },
        120000);
}

TEST(MainWindowTime, AStepAskedForDrawsNoFrameOfTheStepLeft) {
    // Each such frame is a software frame's cores taken from reading and building the step
    // asked for: the view draws again only when the step's preview or surfaces are shown.
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(openEra5(window, {1000, 700}, "t"));
    // The background work done first (the strip filled, the next step read and built ahead),
    // so that only the step asked for can draw.
    ASSERT_TRUE(stripFilled(window));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return !window.view()->inMotion() && !window.isovalueSession()->isPreparing(); },
        30000));
    const auto left = window.view()->renderer().meshes();
    ASSERT_NE(left, nullptr);
    std::size_t framesOfTheStepLeft = 0;
    std::size_t framesSeen = window.view()->framesDrawn();
    QObject::connect(window.view(), &QOpenGLWidget::frameSwapped, &window, [&] {
        const std::size_t drawn = window.view()->framesDrawn();
        if (drawn != framesSeen && window.view()->renderer().meshes() == left) {
            ++framesOfTheStepLeft;
        }
        framesSeen = drawn;
    });
    const std::size_t before = window.view()->framesDrawn();
    // Step 3: neither kept nor read ahead (that is step 1), so it is read after the request.
    window.timeBar()->requestStep(3);
    ASSERT_TRUE(stepShown(window, 3));
    ASSERT_TRUE(QTest::qWaitFor([&] { return window.view()->framesDrawn() > before; }, 10000))
        << "the step itself is drawn";
    EXPECT_NE(window.view()->renderer().meshes(), left);
    EXPECT_EQ(framesOfTheStepLeft, 0U);
}

// Without visiting them, the strip gets every step's clusters (computed in the background,
// without surfaces), with the identities `ensil preprocess --times all` gives at the same
// isovalue and k; the member table's columns per step show the same.
TEST(MainWindowTime, TheStripFillsEveryStepInTheBackgroundAsTheCommandLineClustersThem) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(openEra5(window, {1400, 900}, "t"));
    const ui::ClusterTimeline& strip = *window.findChild<ui::ClusterTimeline*>();
    ASSERT_TRUE(stripFilled(window)) << "the steps not visited are clustered";
    EXPECT_EQ(window.timeBar()->shownStep(), 0) << "without leaving the step shown";

    engine::TimeSeriesRequest request;
    request.selection = {.paths = {ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc"}, .variable = "t"};
    request.steps = {0, 3};
    request.preprocess.isovalue = *window.captureSession().isovalue;
    request.preprocess.clusters = window.memberSelection()->clusterCount();
    const auto steps =
        engine::preprocessTimeSeries(request, [](const std::string&, const std::string&) {});
    ui::MemberTableModel& table = *window.memberTable()->model();
    window.memberTable()->stepsButton()->click();
    ASSERT_TRUE(table.stepColumnsShown());
    for (int s = 0; s < 4; ++s) {
        EXPECT_EQ(strip.stepClusters(s), steps[static_cast<std::size_t>(s)].memberIdentities)
            << "step " << s;
        const QModelIndex cell = table.index(0, ui::MemberTableModel::stepColumn(s));
        EXPECT_EQ(cell.data().toInt(), strip.stepClusters(s).front() + 1) << "step " << s;
    }
    // For the eye: the strip filled and the table's columns per step (see the closing note).
    QScrollBar* across = window.memberTable()->table()->horizontalScrollBar();
    across->setValue(across->maximum());
    window.grab().save(QStringLiteral(ENSIL_TEST_OUTPUT_DIR "/era5_strip_filled.png"));

    // Its GRIB twin is the same data: the same clusters at every step, steps visited or not.
    app::MainWindow twin;
    ASSERT_TRUE(openEra5(twin, {1400, 900}, "t", "era5-levels-members.grib"));
    twin.timeBar()->step(1);
    ASSERT_TRUE(stepShown(twin, 1));
    ASSERT_TRUE(stripFilled(twin));
    const ui::ClusterTimeline& twinStrip = *twin.findChild<ui::ClusterTimeline*>();
    twin.memberTable()->stepsButton()->click();
    twin.memberTable()->table()->horizontalScrollBar()->setValue(
        twin.memberTable()->table()->horizontalScrollBar()->maximum());
    for (int s = 0; s < 4; ++s) {
        EXPECT_EQ(twinStrip.stepClusters(s), strip.stepClusters(s)) << "step " << s;
    }
    twin.grab().save(QStringLiteral(ENSIL_TEST_OUTPUT_DIR "/era5_grib_strip_step1.png"));
}

TEST(MainWindowTime, TheStepOpenedFirstComesBackWithItsMotionMeshes) {
    // The opened step's motion meshes are built after its first frame; stepping on at once
    // must not drop them, or its first frame when visited again draws the full meshes.
    const test::ScopedCacheHome cache;
    test::TempDir dir;
    constexpr data::DemoEnsembleParams kDemo{.members = 12, .nx = 64, .ny = 48, .nz = 12};
    const std::string path = writeTwoDemoSteps(dir, kDemo);
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1000, 700}));
    workbench::IsovalueSession& session = *window.isovalueSession();
    QSignalSpy built(&session, &workbench::IsovalueSession::finished);
    QSignalSpy drawn(window.view(), &QOpenGLWidget::frameSwapped);
    window.openFiles(data::DataSelection{.paths = {path}});
    ASSERT_TRUE(built.wait(120000));
    drawn.clear();
    ASSERT_TRUE(drawn.wait(30000)) << "the opened step's first frame";
    const auto opened = window.view()->renderer().meshes();

    window.timeBar()->step(1);
    ASSERT_TRUE(stepShown(window, 1));
    std::shared_ptr<const data::MeshSet> motionAtReturn;
    QObject::connect(&session, &workbench::IsovalueSession::finished, &window,
                     [&] { motionAtReturn = window.view()->renderer().motionMeshes(); });
    window.timeBar()->step(-1);
    ASSERT_TRUE(stepShown(window, 0));
    ASSERT_EQ(window.view()->renderer().meshes(), opened) << "kept, shown again";
    ASSERT_NE(motionAtReturn, nullptr) << "its first frame again has its motion meshes";
    EXPECT_EQ(motionAtReturn->members.size(), kDemo.members);
    EXPECT_LT(motionAtReturn->members.front().indices.size(),
              opened->members.front().indices.size())
        << "reduced detail";
}

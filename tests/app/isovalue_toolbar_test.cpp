// The isovalue control in the workbench: it gets the loaded variable's histogram, and a value
// committed on it rebuilds the surfaces in the background while the previous ones stay shown.
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <memory>

#include "app/main_window.h"
#include "engine/isovalue_job.h"
#include "engine/picture_title.h"
#include "tests/app/held_job_threads.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/scoped_cache_home.h"
#include "widgets/histogram_strip.h"
#include "widgets/isovalue_control.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"

using namespace ensil;
using ensil::ui::IsovalueControl;

namespace {
// Shows the workbench on a small demo and waits for its first surfaces.
bool showSmallDemo(app::MainWindow& window) {
    if (!test::showWorkbench(window, {1000, 700})) return false;
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    window.loadDemo({.members = 6, .nx = 64, .ny = 32, .nz = 8, .seed = 4});
    return loaded.wait(30000) && (built.count() > 0 || built.wait(60000));
}
}  // namespace

TEST(IsovalueToolbar, ShowsTheHistogramAndKeepsTheLastSurfacesUntilTheNewOnesAreReady) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1000, 700}));
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    window.loadDemo({.members = 6, .nx = 48, .ny = 24, .nz = 8, .seed = 4});
    ASSERT_TRUE(loaded.wait(30000));
    ui::IsovalueControl* control = window.renderToolbar()->isovalueControl();
    const auto& stats = window.overview()->statistics;
    EXPECT_EQ(control->histogram()->counts(), stats.histogram);
    EXPECT_DOUBLE_EQ(control->minimum(), stats.minimum);
    EXPECT_DOUBLE_EQ(control->maximum(), stats.maximum);
    ASSERT_TRUE(built.count() > 0 || built.wait(60000));
    const auto first = window.view()->renderer().meshes();
    ASSERT_NE(first, nullptr);

    // Dragging alone builds nothing; the release does, and until it is done the old surfaces
    // stay on screen.
    QSlider* slider = control->slider();
    built.clear();
    QSignalSpy started(window.isovalueSession(), &workbench::IsovalueSession::started);
    slider->setSliderDown(true);
    slider->setSliderPosition(IsovalueControl::kSliderSteps / 2);
    EXPECT_EQ(started.count(), 0);
    slider->setSliderDown(false);
    EXPECT_EQ(started.count(), 1);
    // The result comes back through the event loop, so it cannot have replaced the old one yet.
    // The title names what is drawn, not the value being built (for large data, seconds).
    const auto titleOf = [&](float isovalue) {
        return QString::fromStdString(engine::pictureTitle(*window.overview()->ensemble, isovalue));
    };
    EXPECT_EQ(window.view()->renderer().meshes(), first) << "the last result stays until then";
    EXPECT_EQ(window.view()->renderer().title(), titleOf(first->isovalue));
    ASSERT_TRUE(built.wait(60000));
    const auto second = window.view()->renderer().meshes();
    ASSERT_NE(second, first);
    EXPECT_NEAR(second->isovalue, control->value(), 1e-3);
    EXPECT_EQ(window.view()->renderer().title(), titleOf(second->isovalue));
    EXPECT_NE(titleOf(second->isovalue), titleOf(first->isovalue));
    EXPECT_NEAR(control->value(), 0.5 * (stats.minimum + stats.maximum),
                (stats.maximum - stats.minimum) / 1000.0);
}

TEST(IsovalueToolbar, ScrubbingPreviewsOnlyTheNewestValueAndEndsOnTheFullSurfacesOfTheRelease) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(showSmallDemo(window));
    workbench::IsovalueSession* session = window.isovalueSession();
    QSignalSpy built(session, &workbench::IsovalueSession::finished);
    ui::IsovalueControl* control = window.renderToolbar()->isovalueControl();
    QSignalSpy shown(session, &workbench::IsovalueSession::previewShown);

    // A drag over twenty values, faster than any preview is built: the first is built, the
    // newest waits, every value between is dropped.
    QSlider* slider = control->slider();
    slider->setSliderDown(true);
    for (int p = 100; p <= 860; p += 40) {
        slider->setSliderPosition(p);
        ASSERT_LE(session->pendingPreviews(), 1) << "at position " << p;
    }
    EXPECT_EQ(session->pendingPreviews(), 1);
    EXPECT_FALSE(window.renderToolbar()->updatesEnabled())
        << "while scrubbing, the toolbar repaints with the preview frames (FramePacedRepaints)";
    const auto last = static_cast<float>(control->value());
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return !shown.isEmpty() && shown.last().at(0).toFloat() == last; }, 60000));
    EXPECT_EQ(session->previewsBuilt(), 2) << "the first value and the newest, nothing between";
    EXPECT_EQ(session->pendingPreviews(), 0);
    const auto preview = window.view()->renderer().meshes();
    ASSERT_NE(preview, nullptr);
    EXPECT_EQ(preview->isovalue, last) << "the view shows the value under the pointer";
    EXPECT_EQ(built.count(), 0) << "no full build while dragging";

    // Dragging back over a value seen is shown from memory, at once, without a build.
    const qsizetype before = shown.count();
    slider->setSliderPosition(100);
    EXPECT_EQ(shown.count(), before + 1);
    EXPECT_EQ(window.view()->renderer().meshes()->isovalue, shown.first().at(0).toFloat())
        << "the first value previewed";
    EXPECT_EQ(session->previewsBuilt(), 2);
    slider->setSliderPosition(860);

    // The release builds the full surfaces; the preview stays until they are ready.
    slider->setSliderDown(false);
    EXPECT_FALSE(session->isPreviewing());
    EXPECT_TRUE(window.renderToolbar()->updatesEnabled()) << "the release repaints it at once";
    EXPECT_EQ(window.view()->renderer().meshes()->isovalue, last);
    ASSERT_TRUE(built.wait(60000));
    const auto final = window.view()->renderer().meshes();
    EXPECT_EQ(final->isovalue, last);
    EXPECT_GT(final->gpuBytes(), 0u);

    // The picture is the one of the surfaces built directly for that isovalue, without a scrub.
    const QSize size(480, 300);
    const QImage scrubbed = window.view()->renderImage(size);
    engine::IsovalueJobInput input;
    input.ensemble = window.overview()->ensemble.get();
    input.moments = window.overview()->moments.get();
    input.options.isovalue = last;
    input.verticalExaggeration = window.view()->renderer().frame().verticalExaggeration();
    const engine::IsovalueOutcome direct = engine::runIsovalueJob(input);
    window.view()->renderer().setMeshes(std::make_shared<data::MeshSet>(direct.meshes));
    const QImage directly = window.view()->renderImage(size);
    ASSERT_FALSE(scrubbed.isNull());
    EXPECT_EQ(scrubbed, directly);
    // And a preview is not: it would have shown the coarser surfaces.
    window.view()->renderer().setMeshes(preview);
    EXPECT_NE(window.view()->renderImage(size), directly);
}

TEST(IsovalueToolbar, APreviewIsBuiltWhileEverySharedWorkerThreadIsBusy) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(showSmallDemo(window));
    workbench::IsovalueSession* session = window.isovalueSession();
    QSignalSpy built(session, &workbench::IsovalueSession::finished);

    // Every thread of the jobs' pool held. (Held on Qt's global pool, as the jobs were before,
    // the window's next repaint waited for them: Qt's raster painting uses it.)
    test::HeldJobThreads jobThreads;
    ASSERT_TRUE(jobThreads.held()) << "the jobs' threads are all held";

    QSignalSpy shown(session, &workbench::IsovalueSession::previewShown);
    QSlider* slider = window.renderToolbar()->isovalueControl()->slider();
    slider->setSliderDown(true);
    slider->setSliderPosition(slider->maximum() / 3);
    const bool previewed = shown.wait(20000);
    jobThreads.release();
    EXPECT_TRUE(previewed) << "the preview waited for a shared thread";
    slider->setSliderDown(false);
    ASSERT_TRUE(built.wait(60000)) << "the release's full surfaces, once the threads are free";
}

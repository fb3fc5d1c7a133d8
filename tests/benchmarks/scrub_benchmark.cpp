// Scrubbing the isovalue in the real workbench window: the paper-sized demo (50 members,
// 256 x 128 x 16) in a 1000 x 600 view; the isovalue slider is held and moved like a pointer
// at 60 events a second across the middle of the range for a few seconds, then released.
// Prints the updates a second (frames drawn showing a new value), the latency from a pointer
// move to the frame showing its value, what a preview took to build, and the time from the
// release to the full-detail surfaces drawn. Needs an X display (xvfb-run -a).
//
//   ensil_scrub_benchmark [--seconds S] [--pictures STEM]
#include <QApplication>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "app/main_window.h"
#include "data/demo_ensemble.h"
#include "data/working_memory.h"
#include "preprocessing/preview_meshes.h"
#include "timing.h"
#include "widgets/isovalue_control.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/workbench_surface_format.h"

using namespace ensil;

namespace {
constexpr double kPointerIntervalMs = 1000.0 / 60.0;

double orZero(const std::vector<double>& values) {
    return values.empty() ? 0.0 : bench::median(values);
}

// Runs the event loop, idle between events as a user's session is (a busy loop here would take
// a core from the workers), until `deadline` (ms on `clock`) or until `done` holds.
template <typename Done>
void runUntil(const QElapsedTimer& clock, double deadlineMs, Done&& done) {
    while (!done()) {
        const double left = deadlineMs - static_cast<double>(clock.nsecsElapsed()) * 1e-6;
        if (left <= 0.0) return;
        QEventLoop loop;
        QTimer::singleShot(std::min(static_cast<int>(std::ceil(left)), 50), &loop,
                           &QEventLoop::quit);
        loop.exec();
    }
}
}  // namespace

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    double seconds = 4.0;
    QString pictures;  // --pictures STEM: STEM_preview.png, the last preview; STEM_full.png
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::string(argv[i]) == "--seconds") seconds = std::max(0.5, std::atof(argv[i + 1]));
        if (std::string(argv[i]) == "--pictures") pictures = QString::fromLocal8Bit(argv[i + 1]);
    }
    QTemporaryDir home;  // the user's settings and cache stay untouched
    qputenv("XDG_CACHE_HOME", home.path().toUtf8());
    qputenv("XDG_CONFIG_HOME", home.path().toUtf8());
    QSurfaceFormat::setDefaultFormat(workbench::workbenchSurfaceFormat());
    QApplication application(argc, argv);

    app::MainWindow window;
    window.resize(1400, 900);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return 1;
    ui::SilhouetteView* view = window.view();
    // The view itself 1000 x 600, whatever the docks around it take.
    window.resize(window.width() + 1000 - view->width(), window.height() + 600 - view->height());
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    const data::DemoEnsembleParams params;
    window.loadDemo(params);
    if (!built.wait(600000)) {
        std::fprintf(stderr, "the demo did not load\n");
        return 1;
    }
    // The preview alone, outside the window: what one update costs the worker, by budget and
    // decimation.
    {
        const engine::EnsembleOverview& o = *window.overview();
        const data::DisplayFrame frame(o.ensemble->grid, 1.0F);
        const float iso = o.defaultIsovalue;
        std::printf("previews of the 51 surfaces at %.1f, headless (full detail: %zu triangles):\n",
                    iso, window.isovalueSession()->result()->triangles);
        for (const std::size_t budget :
             {std::size_t{1} << 14, std::size_t{1} << 15, std::size_t{1} << 16}) {
            {
                const prep::PreviewOptions options{.pointBudget = budget};
                prep::IsovalueMeshes preview;
                const double ms = bench::medianMs(5, [&] {
                    preview =
                        prep::buildPreviewMeshes(*o.ensemble, *o.moments, frame, iso, options);
                });
                const auto s = prep::previewSampling(o.ensemble->grid, budget);
                std::printf(
                    "  %3zu x %3zu x %3zu points, %-10s median %5.0f ms of 5; %7zu triangles "
                    "extracted, %6zu drawn\n",
                    s.indices[0].size(), s.indices[1].size(), s.indices[2].size(),
                    budget == prep::PreviewOptions{}.pointBudget ? "(default)" : "", ms,
                    preview.trianglesExtracted, preview.triangles);
            }
        }
    }
    workbench::IsovalueSession& session = *window.isovalueSession();
    ui::IsovalueControl& control = *window.renderToolbar()->isovalueControl();
    QSlider& slider = *control.slider();

    // When each value was asked for, and each frame drawn with what it showed.
    QElapsedTimer clock;
    std::map<float, double> askedAtMs;
    std::vector<double> latencyMs, previewBuildMs;
    std::vector<double> updateTimesMs;
    float lastDrawn = view->renderer().meshes() ? view->renderer().meshes()->isovalue : 0.0F;
    QObject::connect(&control, &ui::IsovalueControl::isovalueScrubbed, [&](double v) {
        askedAtMs.try_emplace(static_cast<float>(v),
                              static_cast<double>(clock.nsecsElapsed()) * 1e-6);
    });
    std::shared_ptr<const data::MeshSet> lastPreview;
    QObject::connect(&session, &workbench::IsovalueSession::previewShown, [&](float, double s) {
        lastPreview = view->renderer().meshes();
        if (s > 0.0) previewBuildMs.push_back(s * 1e3);
    });
    bool scrubbing = true;
    int framesWhileScrubbing = 0;  // every frame drawn, new value or not
    QObject::connect(view, &QOpenGLWidget::frameSwapped, [&] {
        if (scrubbing) ++framesWhileScrubbing;
        const auto& meshes = view->renderer().meshes();
        if (!scrubbing || !meshes || meshes->isovalue == lastDrawn) return;
        lastDrawn = meshes->isovalue;
        const double now = static_cast<double>(clock.nsecsElapsed()) * 1e-6;
        updateTimesMs.push_back(now);
        if (const auto asked = askedAtMs.find(lastDrawn); asked != askedAtMs.end()) {
            latencyMs.push_back(now - asked->second);
        }
    });

    // The drag: from 30 % to 70 % of the slider, one pointer event every 1/60 s.
    const int from = ui::IsovalueControl::kSliderSteps * 3 / 10;
    const int to = ui::IsovalueControl::kSliderSteps * 7 / 10;
    const double durationMs = seconds * 1000.0;
    const std::size_t framesBefore = view->framesDrawn();
    clock.start();
    slider.setSliderDown(true);
    int events = 0;
    for (double t = 0.0; t < durationMs; t += kPointerIntervalMs) {
        slider.setSliderPosition(from + static_cast<int>((to - from) * t / durationMs));
        ++events;
        runUntil(clock, t + kPointerIntervalMs, [] { return false; });
    }
    if (!pictures.isEmpty()) view->renderImage(view->size()).save(pictures + "_preview.png");
    // The release, and the full-detail surfaces of the value released drawn.
    const std::size_t viewFramesWhileScrubbing = view->framesDrawn() - framesBefore;
    QElapsedTimer release;
    release.start();
    scrubbing = false;
    built.clear();
    slider.setSliderDown(false);
    bool fullDrawn = false;
    const auto fullShown = [&] {
        return built.count() > 0 && session.result() != nullptr &&
               view->renderer().meshes() == session.result()->meshes;
    };
    QObject::connect(view, &QOpenGLWidget::frameSwapped, [&] { fullDrawn = fullShown(); });
    runUntil(clock, 1e9, [&] { return fullDrawn; });
    const double releaseMs = static_cast<double>(release.nsecsElapsed()) * 1e-6;
    if (!pictures.isEmpty()) view->renderImage(view->size()).save(pictures + "_full.png");

    // What a frame of each costs the GUI thread (software OpenGL here): the last preview and the
    // full surfaces, drawn as during a scrub (the motion's resolution) and still.
    // (A frame asked for and waited for until the window has composed it: repaint() draws
    // nothing of a QOpenGLWidget by itself.)
    const auto frameMs = [&](const std::shared_ptr<const data::MeshSet>& meshes, bool moving) {
        view->renderer().setMeshes(meshes);
        if (moving) view->beginInteraction();
        QSignalSpy composed(view, &QOpenGLWidget::frameSwapped);
        const auto oneFrame = [&] {
            view->update();
            if (!composed.wait(60000)) std::fprintf(stderr, "a frame was not composed\n");
        };
        oneFrame();  // the motion's first frame chooses its resolution
        const double ms = bench::medianMs(5, oneFrame);
        if (moving) view->endInteraction();
        return ms;
    };
    const auto full = view->renderer().meshes();
    const double previewMoving = frameMs(lastPreview, true);
    const double fullMoving = frameMs(full, true);
    const double fullStill = frameMs(full, false);

    std::printf(
        "workbench scrub, paper-sized demo (%zu members, %zu x %zu x %zu), %d x %d view, "
        "%.1f s drag, %d pointer events\n",
        params.members, params.nx, params.ny, params.nz, view->width(), view->height(), seconds,
        events);
    std::printf(
        "  updates a second                  %6.1f  (%zu frames with a new value; goal >= 10)\n",
        static_cast<double>(updateTimesMs.size()) / seconds, updateTimesMs.size());
    std::printf(
        "  frames while scrubbing            %zu drawn by the view, %d window compositions\n",
        viewFramesWhileScrubbing, framesWhileScrubbing);
    std::printf("  pointer move to picture           median %6.0f ms, worst %6.0f ms\n",
                orZero(latencyMs),
                latencyMs.empty() ? 0.0 : *std::max_element(latencyMs.begin(), latencyMs.end()));
    std::printf(
        "  a preview built                   median %6.0f ms (%d built, %zu values asked)\n",
        orZero(previewBuildMs), session.previewsBuilt(), askedAtMs.size());
    std::printf(
        "  a frame, preview while scrubbing  median %6.0f ms (full detail: %.0f ms scrubbing, %.0f "
        "ms still; drawn and composed)\n",
        previewMoving, fullMoving, fullStill);
    std::printf("  release to full detail drawn      %6.0f ms  (goal <= 500)\n", releaseMs);
    return 0;
}

// Stepping through time in the real workbench window: the paper-sized demo (ensil generate's
// defaults: 50 members, 256 x 128 x 16) over 10 steps, written as one NetCDF file with a CF
// time dimension and opened in the workbench. Prints, per step, the time from the time bar's
// request to the step's surfaces, clusters and panels handed over, and to its first frame
// drawn (and to its first frame in reduced detail, for a step never seen): first going forward
// through the first half of the steps never seen, each asked for as soon as the last is drawn (read
// and built after the request), then through the second half, each asked for once the user has
// looked at the last long enough for the next to be read and built ahead (MainWindow::readAhead;
// waited for on its signal, at most --look seconds, 3 by default), then going back through them
// (kept in memory). Needs an X display (xvfb-run -a).
//
//   ensil_workbench_time_benchmark [--steps N] [--look SECONDS]
#include <QApplication>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/main_window.h"
#include "data/demo_ensemble.h"
#include "data/netcdf_writer.h"
#include "data/working_memory.h"
#include "timing.h"
#include "widgets/silhouette_view.h"
#include "widgets/time_bar.h"
#include "workbench/isovalue_session.h"
#include "workbench/workbench_surface_format.h"

using namespace ensil;

namespace {
constexpr int kDefaultSteps = 10;

struct Step {
    double startedMs = -1.0;   // the step's data in hand and its surfaces asked for
    double readyMs = -1.0;     // its surfaces, clusters and panels handed over (finished)
    double drawnMs = -1.0;     // and the first frame composed after that (software OpenGL)
    double fullMs = -1.0;      // the first of those at full resolution (once steps pause)
    int framesBefore = 0;      // frames composed between the request and ready
    double previewMs = -1.0;   // a step never seen: its reduced-detail surfaces handed over
    double onScreenMs = -1.0;  // the first frame showing the step, in reduced or full detail
};

// Asks for `step` and waits until its surfaces are on screen and drawn. Ready is when the
// session says the step's surfaces are handed over; drawn, the first frame composed after it
// (the window draws it by itself: the benchmark asks for none).
Step stepTo(app::MainWindow& window, int step) {
    ui::TimeBar& bar = *window.timeBar();
    QElapsedTimer timer;
    Step s;
    const auto now = [&] { return static_cast<double>(timer.nsecsElapsed()) * 1e-6; };
    const QMetaObject::Connection started =
        QObject::connect(window.isovalueSession(), &workbench::IsovalueSession::started, [&] {
            if (s.startedMs < 0) s.startedMs = now();
        });
    const QMetaObject::Connection finished =
        QObject::connect(window.isovalueSession(), &workbench::IsovalueSession::finished, [&] {
            if (s.readyMs < 0 && bar.shownStep() == step) s.readyMs = now();
        });
    const QMetaObject::Connection previewed =
        QObject::connect(window.isovalueSession(), &workbench::IsovalueSession::previewShown, [&] {
            if (s.previewMs < 0 && s.readyMs < 0) s.previewMs = now();
        });
    const QMetaObject::Connection frames =
        QObject::connect(window.view(), &QOpenGLWidget::frameSwapped, [&] {
            if (s.onScreenMs < 0 && (s.previewMs >= 0 || s.readyMs >= 0)) s.onScreenMs = now();
            if (s.readyMs < 0) {
                ++s.framesBefore;
            } else {
                if (s.drawnMs < 0) s.drawnMs = now();
                if (s.fullMs < 0 && !window.view()->inMotion()) s.fullMs = now();
            }
        });
    timer.start();
    bar.requestStep(step);
    const bool shown =
        QTest::qWaitFor([&] { return s.fullMs >= 0 && bar.pendingStep() < 0; }, 600000);
    QObject::disconnect(started);
    QObject::disconnect(finished);
    QObject::disconnect(frames);
    QObject::disconnect(previewed);
    if (!shown) s.readyMs = s.drawnMs = s.fullMs = -1.0;
    return s;
}

void report(const char* what, const std::vector<Step>& steps) {
    std::vector<double> started, ready, drawn, full, frames, onScreen;
    for (const Step& s : steps) {
        onScreen.push_back(s.onScreenMs);
        started.push_back(s.startedMs);
        ready.push_back(s.readyMs);
        drawn.push_back(s.drawnMs);
        full.push_back(s.fullMs);
        frames.push_back(s.framesBefore);
    }
    std::printf("  %-42s median %6.0f ms ready, %6.0f ms drawn, %6.0f ms at full resolution\n",
                what, bench::median(ready), bench::median(drawn), bench::median(full));
    std::printf("  %-42s (surfaces asked for at %.0f ms; %.0f frames composed before ready;\n", "",
                bench::median(started), bench::median(frames));
    std::printf("  %-42s  first frame of the step, in reduced or full detail, at %.0f ms)\n", "",
                bench::median(onScreen));
    // Every step's, not only the median: the goal holds for each step.
    std::printf("  %-42s  each step drawn at:", "");
    for (const double ms : drawn) std::printf(" %.0f", ms);
    std::printf(" ms\n");
}

}  // namespace

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    int kSteps = kDefaultSteps;
    double lookSeconds = 3.0;
    for (int a = 1; a + 1 < argc; ++a) {
        if (std::string(argv[a]) == "--steps") kSteps = std::max(4, std::atoi(argv[a + 1]));
        if (std::string(argv[a]) == "--look") lookSeconds = std::max(0.0, std::atof(argv[a + 1]));
    }
    QTemporaryDir home;
    qputenv("XDG_CACHE_HOME", home.path().toUtf8());
    qputenv("XDG_CONFIG_HOME", home.path().toUtf8());
    QSurfaceFormat::setDefaultFormat(workbench::workbenchSurfaceFormat());
    QApplication application(argc, argv);
    const std::string path = home.filePath(QStringLiteral("demo_steps.nc")).toStdString();
    const data::DemoEnsembleParams params;
    data::TimeCoordinate time{.units = data::kDemoTimeUnits, .values = {}};
    for (int t = 0; t < kSteps; ++t) time.values.push_back(data::kDemoHoursPerStep * t);
    data::writeNetcdfSteps(
        [&](std::size_t t) { return data::makeDemoEnsembleAt(params, t, kSteps).ensemble; }, time,
        path);

    app::MainWindow window;
    window.resize(1400, 900);
    window.show();
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    data::DataSelection selection;
    selection.paths = {path};
    window.openFiles(selection);
    QSignalSpy swapped(window.view(), &QOpenGLWidget::frameSwapped);
    if (!built.wait(600000)) {
        std::fprintf(stderr, "the first step did not load\n");
        return 1;
    }
    // The user steps once the first step is on screen (its first frame, a full-resolution one
    // of several hundred ms on software OpenGL, is not counted against the next step).
    swapped.clear();
    if (!QTest::qWaitFor([&] { return !swapped.isEmpty() && !window.view()->inMotion(); },
                         600000)) {
        std::fprintf(stderr, "the first step was not drawn\n");
        return 1;
    }
    std::printf(
        "workbench, paper-sized demo over %d steps (%zu members, %zu x %zu x %zu), "
        "1400 x 900 window\n",
        kSteps, params.members, params.nx, params.ny, params.nz);
    std::vector<Step> fresh, ahead, kept;
    std::vector<double> lookedMs;
    const int half = kSteps / 2;
    // Each preparation ended since a step was asked for: the next one built ahead.
    QSignalSpy prepared(window.isovalueSession(), &workbench::IsovalueSession::preparationEnded);
    for (int s = 1; s <= half; ++s) {
        prepared.clear();
        fresh.push_back(stepTo(window, s));
    }
    for (int s = half + 1; s < kSteps; ++s) {
        // The user looks at the step until the next is built ahead, for at most --look seconds.
        QElapsedTimer look;
        look.start();
        if (prepared.isEmpty()) prepared.wait(static_cast<int>(lookSeconds * 1000.0));
        lookedMs.push_back(static_cast<double>(look.elapsed()));
        prepared.clear();
        ahead.push_back(stepTo(window, s));
    }
    for (int s = kSteps - 2; s >= 0; --s) kept.push_back(stepTo(window, s));
    report("a step never seen, asked for at once", fresh);
    report("the next, once built ahead", ahead);
    std::printf(
        "  %-42s  (looked at the last step %.0f ms more once it was drawn in full, at most"
        " %.0f s)\n",
        "", bench::median(lookedMs), lookSeconds);
    report("a step seen before (kept in memory)", kept);
    return 0;
}

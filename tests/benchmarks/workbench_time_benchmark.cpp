// Stepping through time in the real workbench window: the paper-sized demo (ensil generate's
// defaults: 50 members, 256 x 128 x 16) over 10 steps, written as one NetCDF file with a CF
// time dimension and opened in the workbench. Prints, per step, the time from the time bar's
// request to the step's surfaces, clusters and panels handed over, and to its first frame
// drawn: first going forward through steps never seen (read and built), then going back
// through them (kept in memory). Needs an X display (xvfb-run -a).
//
//   ensil_workbench_time_benchmark
#include <QApplication>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <cstdio>
#include <vector>

#include "app/isovalue_session.h"
#include "app/main_window.h"
#include "app/workbench_surface_format.h"
#include "data/demo_ensemble.h"
#include "data/netcdf_writer.h"
#include "timing.h"
#include "widgets/silhouette_view.h"
#include "widgets/time_bar.h"

using namespace ensil;

namespace {
constexpr int kSteps = 10;

struct Step {
    double readyMs = -1.0;  // the step's surfaces, clusters and panels handed over
    double drawnMs = -1.0;  // and its first frame drawn (software OpenGL here)
};

// Asks for `step` and waits until its surfaces are on screen and drawn.
Step stepTo(app::MainWindow& window, int step) {
    ui::TimeBar& bar = *window.timeBar();
    QElapsedTimer timer;
    timer.start();
    bar.requestStep(step);
    Step s;
    if (!QTest::qWaitFor([&] { return bar.shownStep() == step && bar.pendingStep() < 0 &&
                                      !window.isovalueSession()->isRunning(); },
                         600000)) {
        return s;
    }
    s.readyMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
    window.view()->repaint();  // the step's first frame
    s.drawnMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
    return s;
}

void report(const char* what, const std::vector<Step>& steps) {
    std::vector<double> ready, drawn;
    for (const Step& s : steps) {
        ready.push_back(s.readyMs);
        drawn.push_back(s.drawnMs);
    }
    std::printf("  %-38s median %6.0f ms ready, %6.0f ms drawn\n", what, bench::median(ready),
                bench::median(drawn));
}
}  // namespace

int main(int argc, char** argv) {
    QTemporaryDir home;
    qputenv("XDG_CACHE_HOME", home.path().toUtf8());
    qputenv("XDG_CONFIG_HOME", home.path().toUtf8());
    QSurfaceFormat::setDefaultFormat(app::workbenchSurfaceFormat());
    QApplication application(argc, argv);
    const std::string path = home.filePath(QStringLiteral("demo_steps.nc")).toStdString();
    const data::DemoEnsembleParams params;
    data::TimeCoordinate time{.units = data::kDemoTimeUnits, .values = {}};
    for (int t = 0; t < kSteps; ++t) time.values.push_back(data::kDemoHoursPerStep * t);
    data::writeNetcdfSteps(
        [&](std::size_t t) { return data::makeDemoEnsembleAt(params, t, kSteps).ensemble; },
        time, path);

    app::MainWindow window;
    window.resize(1400, 900);
    window.show();
    QSignalSpy built(window.isovalueSession(), &app::IsovalueSession::finished);
    data::DataSelection selection;
    selection.paths = {path};
    window.openFiles(selection);
    if (!built.wait(600000)) {
        std::fprintf(stderr, "the first step did not load\n");
        return 1;
    }
    std::printf("workbench, paper-sized demo over %d steps (%zu members, %zu x %zu x %zu), "
                "1400 x 900 window\n",
                kSteps, params.members, params.nx, params.ny, params.nz);
    std::vector<Step> fresh, kept;
    for (int s = 1; s < kSteps; ++s) fresh.push_back(stepTo(window, s));
    for (int s = kSteps - 2; s >= 0; --s) kept.push_back(stepTo(window, s));
    report("a step never seen (read and built)", fresh);
    report("a step seen before (kept in memory)", kept);
    return 0;
}

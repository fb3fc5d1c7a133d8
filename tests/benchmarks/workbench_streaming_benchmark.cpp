// The workbench on an ensemble larger than its memory budget (issue 20), in the real window:
// the file opened with a --memory-limit its in-memory peak does not fit, so the workbench reads
// a thinned copy slab by slab and builds the surfaces from the whole data in slabs. Prints the
// time to the copy on screen (statistics, histogram, floor), to the first isovalue's surfaces
// from the whole data, to a second isovalue's, and the process's peak resident memory since the
// window opened the file, against the limit. Needs an X display (xvfb-run -a).
//
//   ensil_workbench_streaming_benchmark --file FILE.nc [--memory-limit 1GiB] [--iso2 VALUE]
//                                       [--screenshot PATH.png]
//
// `ensil generate --members 200 --grid 256x256x64 --out FILE.nc` writes issue 20's 3.4 GB
// ensemble. Like every benchmark here it never fails on a target.
#include <QApplication>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/main_window.h"
#include "data/working_memory.h"
#include "engine/ensemble_overview.h"
#include "engine/run_memory.h"
#include "engine/streaming_run.h"
#include "workbench/isovalue_session.h"
#include "workbench/workbench_surface_format.h"

using namespace ensil;

namespace {
double mib(std::size_t bytes) { return static_cast<double>(bytes) / 1048576.0; }
}  // namespace

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    QSurfaceFormat::setDefaultFormat(workbench::workbenchSurfaceFormat());
    QApplication application(argc, argv);
    std::string file, limitText = "1GiB", screenshot;
    double iso2 = std::nan("");
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--file") {
            file = argv[i + 1];
        } else if (a == "--memory-limit") {
            limitText = argv[i + 1];
        } else if (a == "--iso2") {
            iso2 = std::atof(argv[i + 1]);
        } else if (a == "--screenshot") {
            screenshot = argv[i + 1];
        } else {
            std::fprintf(stderr, "unknown option %s (see the file's first lines)\n", a.c_str());
            return 2;
        }
    }
    std::string problem;
    const auto limit = engine::parseMemorySize(limitText, problem);
    if (file.empty() || !limit) {
        std::fprintf(stderr, "give --file FILE.nc and a valid --memory-limit %s\n",
                     problem.c_str());
        return 2;
    }
    app::MainWindow window;
    window.resize(1400, 900);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return 1;
    window.setMemoryLimit(*limit);
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    QSignalSpy failed(&window, &app::MainWindow::loadingFailed);
    QSignalSpy buildFailed(window.isovalueSession(), &workbench::IsovalueSession::failed);
    const engine::RunMemoryMeter meter;
    QElapsedTimer timer;
    timer.start();
    window.openFiles({.paths = {file}});
    const bool ok = QTest::qWaitFor(
        [&] { return !built.isEmpty() || !failed.isEmpty() || !buildFailed.isEmpty(); }, 3600000);
    const double surfacesS = static_cast<double>(timer.elapsed()) / 1000.0;
    if (!ok || built.isEmpty()) {
        std::fprintf(stderr, "no surfaces: %s%s\n",
                     failed.isEmpty() ? "" : failed.front().front().toString().toUtf8().constData(),
                     buildFailed.isEmpty()
                         ? ""
                         : buildFailed.front().front().toString().toUtf8().constData());
        return 1;
    }
    const engine::EnsembleOverview& overview = *window.overview();
    std::printf("%s; --memory-limit %s (%.0f MiB)\n", file.c_str(), limitText.c_str(), mib(*limit));
    if (overview.streamed) {
        std::printf("streamed: a copy at %s (%.0f MiB), slab passes within %.0f MiB\n",
                    engine::everyNthPoint(overview.streamed->stride).c_str(),
                    mib(overview.ensemble->bytes()), mib(overview.streamed->plan.memoryLimit));
    } else {
        std::printf("opened in memory (the limit holds it)\n");
    }
    std::printf("first isovalue %.4g: surfaces from the whole data %8.2f s after opening\n",
                static_cast<double>(*window.captureSession().isovalue), surfacesS);
    if (!std::isnan(iso2)) {
        built.clear();
        timer.restart();
        session::SessionState state = window.captureSession();
        state.isovalue = static_cast<float>(iso2);
        window.applySession(state);
        if (!built.wait(3600000)) return 1;
        std::printf("second isovalue %.4g: surfaces %8.2f s after the change\n", iso2,
                    static_cast<double>(timer.elapsed()) / 1000.0);
    }
    if (const auto memory = meter.read()) {
        std::printf(
            "peak resident %.0f MiB, %.0f MiB of it before opening: %.0f MiB taken "
            "(%.2f of the limit)\n",
            mib(memory->peakResident), mib(memory->residentAtStart),
            mib(memory->peakResident - memory->residentAtStart),
            static_cast<double>(memory->peakResident - memory->residentAtStart) /
                static_cast<double>(*limit));
    }
    if (!screenshot.empty()) {
        QString error;
        if (!window.saveScreenshot(QString::fromStdString(screenshot), &error)) {
            std::fprintf(stderr, "screenshot: %s\n", error.toUtf8().constData());
        }
        window.grab().save(QString::fromStdString(screenshot).replace(".png", "-window.png"));
    }
    return 0;
}

// How quickly the workbench reopens a project: a project of the paper-sized demo (50 members,
// 256 x 128 x 16, isovalue 30 m/s) is saved, then opened in fresh windows: first with an empty
// mesh cache (meshes, similarity and clustering are computed), then again with the cache the
// first opening filled. Prints the time from openProject() to projectOpened() (data loaded,
// surfaces built, selection applied) for each, with the share of the isovalue job. Needs an X
// display (xvfb-run -a).
//
//   ensil_project_reopen_benchmark [--runs N]
#include <QApplication>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/main_window.h"
#include "data/working_memory.h"
#include "session/project_file.h"
#include "timing.h"
#include "workbench/isovalue_session.h"
#include "workbench/workbench_surface_format.h"

namespace {
struct Reopening {
    double loadedMs = -1.0;  // the data loaded (demo made, statistics, moments)
    double openedMs = -1.0;  // the surfaces shown and the project applied
    bool fromCache = false;
};

// Opens the project in a new window and times it.
Reopening reopen(const QString& path) {
    Reopening r;
    ensil::app::MainWindow window;
    window.resize(1400, 900);
    window.show();
    QElapsedTimer timer;
    QObject::connect(&window, &ensil::app::MainWindow::ensembleLoaded, &window,
                     [&] { r.loadedMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6; });
    QSignalSpy opened(&window, &ensil::app::MainWindow::projectOpened);
    timer.start();
    if (!window.openProject(path) || !opened.wait(600000)) return r;
    r.openedMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
    r.fromCache = window.isovalueSession()->result()->fromCache;
    return r;
}
}  // namespace

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    int runs = 3;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
    }
    QTemporaryDir home;
    qputenv("XDG_CACHE_HOME", home.path().toUtf8());
    qputenv("XDG_CONFIG_HOME", home.path().toUtf8());
    QSurfaceFormat::setDefaultFormat(ensil::workbench::workbenchSurfaceFormat());
    QApplication app(argc, argv);
    const QString path = home.filePath(QStringLiteral("paper.ensil"));
    {
        ensil::session::SessionState project;
        project.demo = true;
        project.isovalue = 30.0F;
        ensil::session::saveProject(project, path);
    }
    const Reopening cold = reopen(path);
    std::printf("project of the paper-sized demo (50 members, 256 x 128 x 16, isovalue 30)\n");
    std::printf(
        "  first opening, empty cache      %8.0f ms  (data loaded at %.0f ms; meshes "
        "from the cache: %s)\n",
        cold.openedMs, cold.loadedMs, cold.fromCache ? "yes" : "no");
    std::vector<double> warm, loaded, surfaces;
    for (int r = 0; r < runs; ++r) {
        const Reopening again = reopen(path);
        if (!again.fromCache) std::printf("  (run %d did not use the cache)\n", r + 1);
        warm.push_back(again.openedMs);
        loaded.push_back(again.loadedMs);
        surfaces.push_back(again.openedMs - again.loadedMs);
    }
    std::printf("  reopening, warm cache (median)  %8.0f ms  over %d runs (min %.0f, max %.0f)\n",
                ensil::bench::median(warm), runs, *std::min_element(warm.begin(), warm.end()),
                *std::max_element(warm.begin(), warm.end()));
    std::printf("    of which loading the data     %8.0f ms\n", ensil::bench::median(loaded));
    std::printf("    and the surfaces, from cache  %8.0f ms\n", ensil::bench::median(surfaces));
    return 0;
}

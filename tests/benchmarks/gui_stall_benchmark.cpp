// How long the workbench's GUI thread is kept from its event loop while it loads and
// preprocesses the paper-sized demo (50 members, 256 x 128 x 16): the window is shown, the demo
// loaded (generation, statistics, moments on a worker) and the first isovalue built (meshes,
// similarity, clustering on a worker, with a cold mesh cache), and then frames are drawn for a
// second. An EventLoopStallMonitor (5 ms timer) gives the longest stall and the 99th
// percentile per phase; every event that took longer than --report-ms to handle is listed with
// its receiver, so a stall can be traced to what caused it. Last, it orbits the camera for two
// seconds (a left drag, mouse moves at 60 Hz) and counts the frames shown, with and without
// the lower resolution while moving. Needs an X display (xvfb-run -a).
//
//   ensil_gui_stall_benchmark [--members N] [--grid NXxNYxNZ] [--report-ms MS] [--warm-cache]
//                             [--samples N]
#include <QApplication>
#include <QElapsedTimer>
#include <QEvent>
#include <QEventLoop>
#include <QMetaEnum>
#include <QMouseEvent>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <QWindow>
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

#include "app/main_window.h"
#include "data/working_memory.h"
#include "widgets/silhouette_view.h"
#include "workbench/event_loop_stall_monitor.h"
#include "workbench/isovalue_session.h"
#include "workbench/workbench_surface_format.h"

namespace {

// CPU time of the calling thread: what the GUI thread computed itself, as against waiting
// for a core or for the OpenGL driver's threads.
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

struct SlowEvent {
    double ms;
    double cpuMs;  // of the GUI thread
    int depth;     // 0: delivered by the event loop; more: sent from inside another handler
    QString what;
};

// Times every event delivery, so a stall can be blamed on a receiver and an event type.
class TimingApplication : public QApplication {
public:
    TimingApplication(int& argc, char** argv, double reportMs)
        : QApplication(argc, argv), m_reportMs(reportMs) {}

    bool notify(QObject* receiver, QEvent* event) override {
        QElapsedTimer timer;
        timer.start();
        const double cpuStart = threadCpuMs();
        const QEvent::Type type = event->type();  // the event may be gone after delivery
        const QString receiverText = describe(receiver);
        ++m_depth;
        const bool handled = QApplication::notify(receiver, event);
        --m_depth;
        const double ms = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
        if (ms >= m_reportMs) {
            const char* typeName = QMetaEnum::fromType<QEvent::Type>().valueToKey(type);
            m_slow.push_back({ms, threadCpuMs() - cpuStart, m_depth,
                              QStringLiteral("%1 to %2")
                                  .arg(typeName != nullptr ? typeName : "event")
                                  .arg(receiverText)});
        }
        return handled;
    }

    [[nodiscard]] std::vector<SlowEvent> takeSlowEvents() { return std::exchange(m_slow, {}); }
    void forgetSlowEvents() { m_slow.clear(); }

private:
    static QString describe(QObject* o) {
        QString text = QString::fromLatin1(o->metaObject()->className());
        if (!o->objectName().isEmpty()) text += QLatin1Char(' ') + o->objectName();
        return text;
    }

    double m_reportMs;
    int m_depth = 0;
    std::vector<SlowEvent> m_slow;
};

struct Phase {
    const char* name;
    ensil::workbench::StallSummary stalls;
    double seconds;
    std::vector<SlowEvent> slowEvents;
};

void printPhase(const Phase& p) {
    std::printf("%-34s %7.2f s  %6zu samples  longest %7.1f ms  p99 %6.1f ms  median %5.2f ms\n",
                p.name, p.seconds, p.stalls.samples, p.stalls.longestMs, p.stalls.percentile99Ms,
                p.stalls.medianMs);
    std::vector<SlowEvent> slow = p.slowEvents;
    std::sort(slow.begin(), slow.end(),
              [](const SlowEvent& a, const SlowEvent& b) { return a.ms > b.ms; });
    if (slow.size() > 8) slow.resize(8);
    for (const SlowEvent& e : slow) {
        std::printf("    %7.1f ms (GUI thread computing %6.1f ms) %*s%s\n", e.ms, e.cpuMs,
                    2 * e.depth, "", qPrintable(e.what));
    }
}

// Runs the real event loop (no polling, no sleeping, which would read as stalls) for `ms`.
void runEventLoopFor(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

// Runs the event loop until `done` or the timeout; false on timeout.
template <typename Done>
bool waitUntil(Done done, int timeoutMs) {
    QElapsedTimer t;
    t.start();
    while (!done()) {
        if (t.elapsed() > timeoutMs) return false;
        runEventLoopFor(20);
    }
    return true;
}

// Orbits the view with a left drag for two seconds, a mouse move every 16 ms, and returns the
// frames shown per second.
double orbitFramesPerSecond(ensil::ui::SilhouetteView& view) {
    int frames = 0;
    const auto counting = QObject::connect(&view, &QOpenGLWidget::frameSwapped, [&] { ++frames; });
    QPoint at(view.width() / 3, view.height() / 2);
    const auto send = [&](QEvent::Type type, Qt::MouseButton button, Qt::MouseButtons buttons) {
        QMouseEvent event(type, at, view.mapToGlobal(at), button, buttons, Qt::NoModifier);
        QApplication::sendEvent(&view, &event);
    };
    send(QEvent::MouseButtonPress, Qt::LeftButton, Qt::LeftButton);
    QTimer mover;
    mover.setInterval(16);
    QObject::connect(&mover, &QTimer::timeout, [&] {
        at.rx() += 2;
        send(QEvent::MouseMove, Qt::NoButton, Qt::LeftButton);
    });
    frames = 0;
    QElapsedTimer clock;
    clock.start();
    mover.start();
    runEventLoopFor(2000);
    mover.stop();
    const double perSecond = frames / (static_cast<double>(clock.elapsed()) / 1000.0);
    send(QEvent::MouseButtonRelease, Qt::LeftButton, Qt::NoButton);
    runEventLoopFor(300);  // the still frame
    QObject::disconnect(counting);
    return perSecond;
}

}  // namespace

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    ensil::data::DemoEnsembleParams params;
    double reportMs = 20.0;
    bool warmCache = false;
    // As the workbench asks for, unless --samples says otherwise (to see what it costs).
    int samples = ensil::workbench::workbenchSurfaceFormat().samples();
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--members" && i + 1 < argc) params.members = std::strtoul(argv[++i], nullptr, 10);
        if (a == "--grid" && i + 1 < argc) {
            std::sscanf(argv[++i], "%zux%zux%zu", &params.nx, &params.ny, &params.nz);
        }
        if (a == "--report-ms" && i + 1 < argc) reportMs = std::atof(argv[++i]);
        if (a == "--warm-cache") warmCache = true;
        if (a == "--samples" && i + 1 < argc) samples = std::atoi(argv[++i]);
    }
    QTemporaryDir cache;
    // A cold mesh cache unless asked otherwise: the isovalue job then does the whole work.
    if (!warmCache) qputenv("XDG_CACHE_HOME", cache.path().toUtf8());
    QSurfaceFormat format = ensil::workbench::workbenchSurfaceFormat();
    format.setSamples(samples);
    QSurfaceFormat::setDefaultFormat(format);
    TimingApplication app(argc, argv, reportMs);
    QCoreApplication::setOrganizationName(QStringLiteral("ensil-benchmark"));
    QCoreApplication::setApplicationName(QStringLiteral("ensil-gui-stall-benchmark"));
    QSettings().clear();  // no remembered window layout

    ensil::workbench::EventLoopStallMonitor monitor(5);
    std::vector<Phase> phases;
    QElapsedTimer clock;
    auto beginPhase = [&] {
        app.forgetSlowEvents();
        monitor.start();
        clock.restart();
    };
    auto endPhase = [&](const char* name) {
        monitor.stop();
        phases.push_back({name, monitor.summary(), static_cast<double>(clock.elapsed()) / 1000.0,
                          app.takeSlowEvents()});
    };

    clock.start();
    beginPhase();
    ensil::app::MainWindow window;
    window.show();
    if (!waitUntil([&] { return window.windowHandle() && window.windowHandle()->isExposed(); },
                   30000)) {
        std::fprintf(stderr, "the window was not shown (run under xvfb-run -a)\n");
        return 1;
    }
    runEventLoopFor(300);  // first GL initialisation and paints
    endPhase("window shown (GL init, first frames)");

    // Phases end exactly when the workbench says a step is done, so the first frame of the
    // result counts as drawing, not as preprocessing.
    bool built = false;
    QString failure;
    QObject::connect(&window, &ensil::app::MainWindow::ensembleLoaded, [&] {
        endPhase("loading (demo, statistics, moments)");
        beginPhase();
    });
    QObject::connect(&window, &ensil::app::MainWindow::loadingFailed,
                     [&](const QString& m) { failure = m; });
    QObject::connect(window.isovalueSession(), &ensil::workbench::IsovalueSession::finished, [&] {
        built = true;
        endPhase("preprocessing (the isovalue job)");
        beginPhase();
    });
    QObject::connect(window.isovalueSession(), &ensil::workbench::IsovalueSession::failed,
                     [&](const QString& m) { failure = m; });

    beginPhase();
    window.loadDemo(params);
    if (!waitUntil([&] { return built || !failure.isEmpty(); }, 600000) || !failure.isEmpty()) {
        std::fprintf(stderr, "loading or preprocessing failed: %s\n", qPrintable(failure));
        return 1;
    }
    runEventLoopFor(1000);
    endPhase("drawing the result (1 s)");
    // A frame of the same scene again: what the first one spent once (uploads, the driver
    // compiling shader variants) against what every frame costs.
    beginPhase();
    window.view()->update();
    runEventLoopFor(500);
    endPhase("drawing it once more (0.5 s)");

    ensil::ui::SilhouetteView& view = *window.view();
    view.setAdaptiveResolution(true);
    const double adaptiveFps = orbitFramesPerSecond(view);
    view.setAdaptiveResolution(false);
    const double fullFps = orbitFramesPerSecond(view);
    view.setAdaptiveResolution(true);

    const auto* result = window.isovalueSession()->result();
    std::printf(
        "ensil GUI stall benchmark: demo %zu members, %zu x %zu x %zu, window %d x %d, "
        "%s mesh cache, %zu triangles, %d samples\n",
        params.members, params.nx, params.ny, params.nz, window.width(), window.height(),
        warmCache ? "warm" : "cold", result != nullptr ? result->triangles : 0, samples);
    std::printf(
        "stall = lateness of a 5 ms timer; events that took >= %.0f ms listed below each "
        "phase (indented: sent from inside the one above)\n",
        reportMs);
    double longestWhileWorking = 0.0;
    for (const Phase& p : phases) {
        printPhase(p);
        if (std::string(p.name).starts_with("loading") ||
            std::string(p.name).starts_with("preprocessing")) {
            longestWhileWorking = std::max(longestWhileWorking, p.stalls.longestMs);
        }
    }
    std::printf("longest stall while loading and preprocessing: %.1f ms (goal <= 50 ms)\n",
                longestWhileWorking);
    std::printf(
        "orbiting (view %d x %d): %.1f frames/s drawn at lower resolution while moving, %.1f at "
        "full resolution\n",
        view.width(), view.height(), adaptiveFps, fullFps);
    // Other processes competing for the cores lengthen every stall: say how busy the machine was.
    std::array<double, 3> load{};
    if (getloadavg(load.data(), 3) == 3) {
        std::printf("load average at the end: %.2f %.2f %.2f on %d cores\n", load[0], load[1],
                    load[2], QThread::idealThreadCount());
    }
    return 0;
}

// The `ensil` executable: subcommands run headless on a QCoreApplication; everything else opens
// the workbench.
#include <QApplication>
#include <QGuiApplication>
#include <QIcon>
#include <QSurfaceFormat>
#include <QTextStream>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/display_loss.h"
#include "app/main_window.h"
#include "cli/command_line.h"
#include "data/platform.h"
#include "data/working_memory.h"
#include "gl/offscreen_context.h"
#include "gl/surface_format.h"
#include "session/version.h"
#include "workbench/workbench_surface_format.h"

namespace {
void setApplicationIdentity() {
    QCoreApplication::setOrganizationName(QStringLiteral("ensil"));
    QCoreApplication::setApplicationName(QStringLiteral("ensil"));
    QCoreApplication::setApplicationVersion(QStringLiteral(ENSIL_VERSION));
}
}  // namespace

int main(int argc, char* argv[]) {
    ensil::data::keepWorkingMemoryForReuse();
    ensil::data::ensurePrivateRuntimeDirectory();
    QStringList args;
    for (int i = 0; i < argc; ++i) args << QString::fromLocal8Bit(argv[i]);
    QTextStream out(stdout);
    QTextStream err(stderr);

    // `ensil render --help` needs no display server or EGL (man pages are made from it at build
    // time, on machines that may have neither).
    const bool helpOnly =
        args.contains(QLatin1String("--help")) || args.contains(QLatin1String("-h"));
    if (args.size() >= 2 && args.at(1) == QLatin1String("render") && !helpOnly) {
        // With no display server, Mesa's surfaceless EGL renders (a batch node).
        if (const auto problem = ensil::gl::prepareOffscreenPlatform()) {
            err << "ensil render: no display server: " << problem->c_str()
                << "; run it under a virtual display instead: xvfb-run -a ensil render ...\n";
            return 4;
        }
        QSurfaceFormat::setDefaultFormat(ensil::gl::preferredSurfaceFormat());
        std::optional<ensil::app::DisplayLossGuard> guard(std::in_place, "ensil render");
        QGuiApplication app(argc, argv);
        guard.reset();
        setApplicationIdentity();
        return ensil::cli::runCommandLine(args, out, err).exitCode;
    }
    if (args.size() >= 2 && args.at(1) == QLatin1String("section") && !helpOnly) {
        // Text needs a QGuiApplication's fonts; Qt's offscreen platform gives them with no
        // display server, and no window is ever shown.
        qputenv("QT_QPA_PLATFORM", "offscreen");
        QGuiApplication app(argc, argv);
        setApplicationIdentity();
        return ensil::cli::runCommandLine(args, out, err).exitCode;
    }
    if (ensil::cli::isHeadlessInvocation(args)) {
        QCoreApplication app(argc, argv);
        setApplicationIdentity();
        return ensil::cli::runCommandLine(args, out, err).exitCode;
    }
    const auto outcome = ensil::cli::runCommandLine(args, out, err);
    if (!outcome.workbench) return outcome.exitCode;
    if (std::string why; !ensil::gl::displayServerAvailable(&why)) {
        // Qt would only say that no platform plugin could be initialised.
        err << "ensil: the workbench needs a display server (X11 or Wayland), and " << why.c_str()
            << ". Run it on a desktop, through ssh -X, or under a virtual display: xvfb-run -a "
               "ensil. `ensil render` draws pictures without one.\n";
        return 4;
    }

    // The default format must be set before the QApplication exists.
    QSurfaceFormat::setDefaultFormat(ensil::workbench::workbenchSurfaceFormat());
    std::optional<ensil::app::DisplayLossGuard> guard(std::in_place, "ensil");
    QApplication app(argc, argv);
    guard.reset();
    setApplicationIdentity();
    // Wayland compositors match the window to the installed desktop entry by this id (X11 ones
    // by WM_CLASS "ensil", the entry's StartupWMClass); ENSIL_APP_ID comes from
    // resources/CMakeLists.txt, which names the installed files. The icon needs Qt's SVG plugin.
    QGuiApplication::setDesktopFileName(QStringLiteral(ENSIL_APP_ID));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/ensil.svg")));
    ensil::app::MainWindow window;
    window.setMemoryLimit(outcome.workbench->memoryLimit);
    window.showAndOpen(outcome.workbench->selection);
    return QApplication::exec();
}

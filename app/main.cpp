// The `ensil` executable: subcommands run headless on a QCoreApplication; everything else opens
// the workbench.
#include <QApplication>
#include <QSurfaceFormat>
#include <QTextStream>
#include <cstdio>
#include <memory>

#include "app/command_line.h"
#include "app/main_window.h"
#include "app/version.h"
#include "gl/surface_format.h"

namespace {
void setApplicationIdentity() {
    QCoreApplication::setOrganizationName(QStringLiteral("ensil"));
    QCoreApplication::setApplicationName(QStringLiteral("ensil"));
    QCoreApplication::setApplicationVersion(QStringLiteral(ENSIL_VERSION));
}
}  // namespace

int main(int argc, char* argv[]) {
    QStringList args;
    for (int i = 0; i < argc; ++i) args << QString::fromLocal8Bit(argv[i]);
    QTextStream out(stdout);
    QTextStream err(stderr);

    if (ensil::app::isHeadlessInvocation(args)) {
        QCoreApplication app(argc, argv);
        setApplicationIdentity();
        return ensil::app::runCommandLine(args, out, err).exitCode;
    }
    const auto outcome = ensil::app::runCommandLine(args, out, err);
    if (!outcome.workbench) return outcome.exitCode;

    // The default format must be set before the QApplication exists.
    QSurfaceFormat::setDefaultFormat(ensil::gl::preferredSurfaceFormat());
    QApplication app(argc, argv);
    setApplicationIdentity();
    ensil::app::MainWindow window;
    window.show();
    if (outcome.workbench->selection.paths.empty()) {
        window.loadDemo();
    } else {
        window.openFiles(outcome.workbench->selection);
    }
    return QApplication::exec();
}

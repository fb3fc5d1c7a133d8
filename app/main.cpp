// The `ensil` executable: subcommands run headless on a QCoreApplication; everything else opens
// the workbench.
#include <QApplication>
#include <QMessageBox>
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
    if (!outcome.workbench->paths.isEmpty()) {
        QMessageBox::information(
            &window, QObject::tr("Opening files"),
            QObject::tr("This version of ensil cannot read data files yet; the readers for "
                        "NetCDF, HDF5 and VTK arrive in the next release. Showing the built-in "
                        "demo ensemble instead.\n\nAsked to open:\n%1")
                .arg(outcome.workbench->paths.join(QLatin1Char('\n'))));
    }
    window.loadDemo();
    return QApplication::exec();
}

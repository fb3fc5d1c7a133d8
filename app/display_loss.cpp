#include "app/display_loss.h"

#include <cstdio>
#include <cstdlib>

namespace ensil::app {
namespace {

QtMessageHandler g_previous = nullptr;
const char* g_command = "ensil";

void sayDisplayLost(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    if (isPlatformStartFailure(type, message)) {
        const QByteArray display = qgetenv("DISPLAY");
        std::fprintf(stderr,
                     "%s: the display server (DISPLAY=%s) stopped answering while ensil started; "
                     "nothing was done. Run it again, or without DISPLAY (`ensil render` then "
                     "draws through EGL).\n",
                     g_command, display.constData());
        std::fflush(stderr);
        std::_Exit(4);
    }
    if (g_previous != nullptr) {
        g_previous(type, context, message);
        return;
    }
    // Qt's default handler cannot be called: say it as it would, and end as it would.
    std::fprintf(stderr, "%s\n", qPrintable(qFormatLogMessage(type, context, message)));
    if (type == QtFatalMsg) std::abort();
}

}  // namespace

bool isPlatformStartFailure(QtMsgType type, const QString& message) {
    return type == QtFatalMsg && message.contains(QLatin1String("Qt platform plugin"));
}

DisplayLossGuard::DisplayLossGuard(const char* command) {
    g_command = command;
    g_previous = qInstallMessageHandler(sayDisplayLost);
}

DisplayLossGuard::~DisplayLossGuard() {
    qInstallMessageHandler(g_previous);
    g_previous = nullptr;
}

}  // namespace ensil::app

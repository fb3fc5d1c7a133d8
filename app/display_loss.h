// A display server that answered ensil's own check (gl::displayServerAvailable) can be gone a
// moment later, when Qt connects to it: a virtual display that `xvfb-run -a` reuses while the last
// one shuts down, on a loaded machine, or an ssh -X session ending. Qt then ends the process with
// qFatal ("no Qt platform plugin could be initialized"): an abort and a core dump. While the
// application object is made, a DisplayLossGuard turns that one message into ensil's own words
// and exit status 4, the status of "no display server". Other messages go where they went.
// Main thread, around the QGuiApplication's construction only.
#pragma once

#include <QString>
#include <QtGlobal>

namespace ensil::app {

class DisplayLossGuard {
public:
    // `command`: how the message names what stopped ("ensil render", "ensil").
    explicit DisplayLossGuard(const char* command);
    ~DisplayLossGuard();
    DisplayLossGuard(const DisplayLossGuard&) = delete;
    DisplayLossGuard& operator=(const DisplayLossGuard&) = delete;
};

// Whether Qt's message says its platform plugin could not start.
bool isPlatformStartFailure(QtMsgType type, const QString& message);

}  // namespace ensil::app

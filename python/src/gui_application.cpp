#include "python/src/gui_application.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QSurfaceFormat>
#include <QThread>
#include <stdexcept>

#include "data/platform.h"
#include "gl/offscreen_context.h"
#include "gl/surface_format.h"

namespace ensil::python {

void ensureGuiApplication(const std::string& caller) {
    if (QCoreApplication::instance() == nullptr) {
        data::ensurePrivateRuntimeDirectory();  // as ensil does: no stray Qt line on the notebook's
                                                // stderr
        if (const auto problem = gl::prepareOffscreenPlatform()) {
            throw std::runtime_error("no display server: " + *problem);
        }
        QSurfaceFormat::setDefaultFormat(gl::preferredSurfaceFormat());
        static int argc = 1;
        static char name[] = "ensil";
        static char* argv[] = {name, nullptr};
        new QGuiApplication(argc, argv);  // never deleted: Qt cannot be started twice
    } else if (qobject_cast<QGuiApplication*>(QCoreApplication::instance()) == nullptr) {
        throw std::runtime_error(
            caller + " needs a QGuiApplication, and this process made a QCoreApplication");
    }
    if (QThread::currentThread() != QCoreApplication::instance()->thread()) {
        throw std::runtime_error(
            caller + " must be called from the thread Qt started on (the first picture's)");
    }
}

}  // namespace ensil::python

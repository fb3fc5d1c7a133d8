// The Qt application pictures need (the renderer's OpenGL, a figure's fonts), made on the first
// picture as `ensil render` makes it: with no display server, on Mesa's surfaceless EGL. It
// lives until the process ends; a QGuiApplication the host made (a Qt console) is used as it
// is. Throws std::runtime_error, naming `caller` ("ensil.render"), when the process has a
// QCoreApplication instead or this is not the thread Qt started on.
#pragma once

#include <string>

namespace ensil::python {

void ensureGuiApplication(const std::string& caller);

}  // namespace ensil::python

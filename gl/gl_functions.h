// The OpenGL function table ensil targets: 4.1 core, the newest macOS offers.
#pragma once

#include <QOpenGLFunctions_4_1_Core>

namespace ensil::gl {
using GlFunctions = QOpenGLFunctions_4_1_Core;
}  // namespace ensil::gl

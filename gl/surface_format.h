// The surface format ensil asks for everywhere (windows, offscreen tests, `ensil render`):
// OpenGL 4.1 core (the newest macOS offers), 24-bit depth, 8-bit stencil, 4x multisampling.
#pragma once

#include <QSurfaceFormat>

namespace ensil::gl {

inline QSurfaceFormat preferredSurfaceFormat(int samples = 4) {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(4, 1);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    format.setSamples(samples);
    return format;
}

}  // namespace ensil::gl

// The surface format of the workbench window (set as the default before the QApplication
// exists): OpenGL 4.1 core as everywhere, but single-sampled. gl::Renderer draws the scene into
// its own single-sampled targets and only copies the result to the window with one full-screen
// pass, so multisampling the window and the view's framebuffer changes no pixel; it only
// multiplies the cost of every repaint of the window (each progress-bar step recomposes it),
// which on a software OpenGL (llvmpipe) kept the GUI thread busy for 50-100 ms a time
// (ensil_gui_stall_benchmark --samples 4 against the default).
#pragma once

#include <QSurfaceFormat>

#include "gl/surface_format.h"

namespace ensil::workbench {

inline QSurfaceFormat workbenchSurfaceFormat() { return gl::preferredSurfaceFormat(0); }

}  // namespace ensil::workbench

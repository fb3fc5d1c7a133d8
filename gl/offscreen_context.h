// An OpenGL 4.1 core context current on no window, for drawing into framebuffer objects
// (`ensil render`, benchmarks). Under a display server (X, Wayland, or Xvfb) it is Qt's own
// offscreen context. With none, as on a batch node, it is an EGL context on Mesa's surfaceless
// platform: Qt 6.4 cannot make one itself (its EGL platforms want a screen), so ensil starts Qt's
// eglfs platform on the surfaceless EGL display and adopts a context made with plain EGL.
#pragma once

#include <QOffscreenSurface>
#include <memory>
#include <optional>
#include <string>

class QOpenGLContext;

namespace ensil::gl {

// Whether Qt will find a display server for windows: on Linux, WAYLAND_DISPLAY is set, or the
// X display DISPLAY names answers (or the user chose a platform through QT_QPA_PLATFORM);
// elsewhere, always. When not, `why` (if given) says what is missing.
bool displayServerAvailable(std::string* why = nullptr);

// Call before the QGuiApplication exists. With a display server (or a platform the user chose
// through QT_QPA_PLATFORM) it changes nothing and returns nothing. Without one, it checks that
// EGL can render with no display and sets Qt up for it; if EGL cannot, it returns what to do.
std::optional<std::string> prepareOffscreenPlatform();

// Whether prepareOffscreenPlatform() chose surfaceless EGL.
bool renderingWithoutDisplay();

class OffscreenContext {
public:
    OffscreenContext();  // needs a QGuiApplication; throws std::runtime_error
    ~OffscreenContext();
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    [[nodiscard]] QOpenGLContext& context() const { return *m_context; }

private:
    struct Egl;
    std::unique_ptr<Egl> m_egl;  // the native context, with no display server only
    std::unique_ptr<QOpenGLContext> m_context;
    QOffscreenSurface m_surface;
};

}  // namespace ensil::gl

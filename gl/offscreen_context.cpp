#include "gl/offscreen_context.h"

#include <QtGui/qopenglcontext_platform.h>

#include <QOpenGLContext>
#include <stdexcept>

#include "gl/surface_format.h"

#if defined(ENSIL_HAVE_EGL)
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif
#if defined(ENSIL_HAVE_XCB)
#include <xcb/xcb.h>
#endif

namespace ensil::gl {
namespace {
bool g_withoutDisplay = false;
QtMessageHandler g_previousHandler = nullptr;

// eglfs complains that the stand-in framebuffer device describes no screen, and Qt that llvmpipe
// is slow: true, and of no use to someone rendering a picture in a batch job.
void dropEglfsNoise(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    if (type == QtWarningMsg &&
        (message.startsWith(QLatin1String("eglconvenience: Could not")) ||
         message.startsWith(QLatin1String("Running on a software rasterizer")))) {
        return;
    }
    if (g_previousHandler != nullptr) g_previousHandler(type, context, message);
}

#if defined(ENSIL_HAVE_EGL)
// Mesa picks the platform of eglGetDisplay(EGL_DEFAULT_DISPLAY), Qt's call, from EGL_PLATFORM;
// ensil makes its own context on the same display.
EGLDisplay surfacelessDisplay() { return eglGetDisplay(EGL_DEFAULT_DISPLAY); }

std::optional<std::string> checkSurfacelessEgl() {
    const EGLDisplay display = surfacelessDisplay();
    if (display == EGL_NO_DISPLAY || eglInitialize(display, nullptr, nullptr) == EGL_FALSE) {
        return "EGL cannot open a display without one (EGL_PLATFORM=" +
               qEnvironmentVariable("EGL_PLATFORM").toStdString() +
               "; Mesa's surfaceless platform, in libegl-mesa0, can)";
    }
    return std::nullopt;
}

// A configuration for desktop OpenGL on pbuffers. Qt reads the context's format (renderable
// type, then version and profile) through it, so the context is made with one.
EGLConfig desktopGlConfig(EGLDisplay display) {
    // clang-format off
    const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                             EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                             EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                             EGL_NONE};
    // clang-format on
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (eglChooseConfig(display, wanted, &config, 1, &count) == EGL_FALSE || count < 1) {
        throw std::runtime_error("EGL offers no configuration for desktop OpenGL here");
    }
    return config;
}
#endif
}  // namespace

struct OffscreenContext::Egl {
#if defined(ENSIL_HAVE_EGL)
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    ~Egl() {
        if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
    }
#endif
};

bool displayServerAvailable(std::string* why) {
#if defined(Q_OS_LINUX)
    for (const char* variable : {"WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}) {
        if (!qEnvironmentVariableIsEmpty(variable)) return true;
    }
    const QByteArray display = qgetenv("DISPLAY");
    if (display.isEmpty()) {
        if (why != nullptr) *why = "there is none (DISPLAY and WAYLAND_DISPLAY are empty)";
        return false;
    }
#if defined(ENSIL_HAVE_XCB)
    // A DISPLAY left behind (an ssh -X session that ended) would make Qt abort at start-up.
    xcb_connection_t* connection = xcb_connect(display.constData(), nullptr);
    const bool answers = xcb_connection_has_error(connection) == 0;
    xcb_disconnect(connection);
    if (!answers) {
        if (why != nullptr) {
            *why = "the X display '" + display.toStdString() + "' (DISPLAY) does not answer";
        }
        return false;
    }
#endif
    return true;
#else
    (void)why;
    return true;
#endif
}

std::optional<std::string> prepareOffscreenPlatform() {
    std::string why;
    if (displayServerAvailable(&why)) return std::nullopt;
#if defined(ENSIL_HAVE_EGL)
    // Qt must not try the X display that does not answer.
    qunsetenv("DISPLAY");
    if (qEnvironmentVariableIsEmpty("EGL_PLATFORM")) qputenv("EGL_PLATFORM", "surfaceless");
    if (auto problem = checkSurfacelessEgl()) return why + ", and " + *problem;
    // eglfs insists on a framebuffer device for the screen's size and on input devices; a
    // batch render needs neither.
    qputenv("QT_QPA_PLATFORM", "eglfs");
    qputenv("QT_QPA_EGLFS_INTEGRATION", "none");
    qputenv("QT_QPA_EGLFS_FB", "/dev/null");
    qputenv("QT_QPA_EGLFS_DISABLE_INPUT", "1");
    g_previousHandler = qInstallMessageHandler(dropEglfsNoise);
    g_withoutDisplay = true;
    return std::nullopt;
#else
    return why + ", and this build of ensil has no EGL";
#endif
}

bool renderingWithoutDisplay() { return g_withoutDisplay; }

OffscreenContext::OffscreenContext() {
    const QSurfaceFormat format = preferredSurfaceFormat(0);
#if defined(ENSIL_HAVE_EGL)
    if (g_withoutDisplay) {
        m_egl = std::make_unique<Egl>();
        m_egl->display = surfacelessDisplay();
        if (eglBindAPI(EGL_OPENGL_API) == EGL_FALSE) {
            throw std::runtime_error("EGL cannot render desktop OpenGL here");
        }
        // clang-format off
        const EGLint attributes[] = {
            EGL_CONTEXT_MAJOR_VERSION, format.majorVersion(),
            EGL_CONTEXT_MINOR_VERSION, format.minorVersion(),
            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
            EGL_NONE};
        // clang-format on
        m_egl->context = eglCreateContext(m_egl->display, desktopGlConfig(m_egl->display),
                                          EGL_NO_CONTEXT, attributes);
        if (m_egl->context == EGL_NO_CONTEXT) {
            throw std::runtime_error("EGL cannot create an OpenGL 4.1 core context (error 0x" +
                                     QByteArray::number(eglGetError(), 16).toStdString() + ")");
        }
        m_context.reset(QNativeInterface::QEGLContext::fromNative(m_egl->context, m_egl->display));
    }
#endif
    if (!m_context) {
        m_context = std::make_unique<QOpenGLContext>();
        m_context->setFormat(format);
        if (!m_context->create()) {
            throw std::runtime_error("cannot create an OpenGL 4.1 context for rendering");
        }
    }
    m_surface.setFormat(m_context->format());
    m_surface.create();
    if (!m_context->makeCurrent(&m_surface)) {
        throw std::runtime_error("cannot make the OpenGL context current");
    }
}

OffscreenContext::~OffscreenContext() {
    if (m_context) m_context->doneCurrent();
    m_context.reset();  // before the native context it may have adopted
}

}  // namespace ensil::gl

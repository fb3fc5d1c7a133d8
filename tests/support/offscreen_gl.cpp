#include "tests/support/offscreen_gl.h"

#include <cstdlib>

#include "gl/surface_format.h"

namespace ensil::test {

void OffscreenGlTest::SetUp() {
    const QSurfaceFormat format = gl::preferredSurfaceFormat();
    m_surface = std::make_unique<QOffscreenSurface>();
    m_surface->setFormat(format);
    m_surface->create();
    m_context = std::make_unique<QOpenGLContext>();
    m_context->setFormat(format);
    QString problem;
    if (!m_context->create()) {
        problem = QStringLiteral("cannot create an OpenGL context");
    } else if (m_context->format().version() < qMakePair(4, 1) ||
               m_context->format().profile() != QSurfaceFormat::CoreProfile) {
        problem = QStringLiteral("the OpenGL context is %1.%2, not 4.1 core")
                      .arg(m_context->format().majorVersion())
                      .arg(m_context->format().minorVersion());
    } else if (!m_context->makeCurrent(m_surface.get())) {
        problem = QStringLiteral("cannot make the OpenGL context current");
    }
    if (!problem.isEmpty()) {
        if (std::getenv("CI") != nullptr) {
            FAIL() << problem.toStdString() << " (CI is set: GL tests must run)";
        }
        GTEST_SKIP() << problem.toStdString();
    }
    QOpenGLFramebufferObjectFormat fboFormat;
    fboFormat.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    fboFormat.setSamples(4);
    m_fbo = std::make_unique<QOpenGLFramebufferObject>(kWidth, kHeight, fboFormat);
    ASSERT_TRUE(m_fbo->isValid()) << "cannot create a framebuffer object";
}

void OffscreenGlTest::TearDown() {
    if (m_context && QOpenGLContext::currentContext() == m_context.get()) {
        m_fbo.reset();
        m_context->doneCurrent();
    }
}

unsigned OffscreenGlTest::framebuffer() {
    m_fbo->bind();
    return m_fbo->handle();
}

QImage OffscreenGlTest::grab() { return m_fbo->toImage(); }

}  // namespace ensil::test

#include "tests/support/offscreen_gl.h"

#include <QOpenGLContext>
#include <cstdlib>
#include <exception>

namespace ensil::test {

void OffscreenGlTest::SetUp() {
    QString problem;
    try {
        m_context = std::make_unique<gl::OffscreenContext>();
        const QSurfaceFormat format = m_context->context().format();
        if (format.version() < qMakePair(4, 1) || format.profile() != QSurfaceFormat::CoreProfile) {
            problem = QStringLiteral("the OpenGL context is %1.%2, not 4.1 core")
                          .arg(format.majorVersion())
                          .arg(format.minorVersion());
        }
    } catch (const std::exception& e) {
        problem = QString::fromUtf8(e.what());
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
    m_fbo.reset();  // while its context is current
    m_context.reset();
}

unsigned OffscreenGlTest::framebuffer() {
    m_fbo->bind();
    return m_fbo->handle();
}

QImage OffscreenGlTest::grab() { return m_fbo->toImage(); }

}  // namespace ensil::test

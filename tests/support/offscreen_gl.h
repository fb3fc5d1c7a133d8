// A GoogleTest fixture with the product's OpenGL 4.1 core offscreen context (gl::OffscreenContext,
// as `ensil render` uses) current and a multisampled framebuffer object of fixed size to draw into.
// Works under Xvfb with Mesa's llvmpipe. When no context can be made the test fails if the CI
// environment variable is set (CI must never silently skip GL tests) and is skipped, with the
// reason, otherwise.
#pragma once

#include <gtest/gtest.h>

#include <QImage>
#include <QOpenGLFramebufferObject>
#include <memory>

#include "gl/offscreen_context.h"

namespace ensil::test {

class OffscreenGlTest : public ::testing::Test {
protected:
    static constexpr int kWidth = 320;
    static constexpr int kHeight = 240;

    void SetUp() override;
    void TearDown() override;

    // Binds the framebuffer object; its id for Renderer::render.
    unsigned framebuffer();
    // The framebuffer's pixels (resolved from multisampling).
    QImage grab();

    std::unique_ptr<gl::OffscreenContext> m_context;
    std::unique_ptr<QOpenGLFramebufferObject> m_fbo;
};

}  // namespace ensil::test

// A GoogleTest fixture holding an initialised gl::Renderer on the offscreen context: draw()
// renders a frame and returns its pixels, project() says where a display-space point lands.
#pragma once

#include <QImage>
#include <QPoint>
#include <cmath>
#include <glm/vec4.hpp>

#include "gl/renderer.h"
#include "tests/support/offscreen_gl.h"

namespace ensil::test {

class RendererFixture : public OffscreenGlTest {
protected:
    void SetUp() override {
        OffscreenGlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        m_renderer.initialize();
    }
    void TearDown() override {
        if (m_renderer.isInitialized()) m_renderer.releaseGpuResources();
        OffscreenGlTest::TearDown();
    }
    QImage draw() {
        m_renderer.render(framebuffer(), kWidth, kHeight);
        return grab();
    }
    // Pixel position (top-left origin) of a display-space point.
    [[nodiscard]] QPoint project(const glm::vec3& p) const {
        const glm::vec4 c =
            m_renderer.camera().viewProjection(float(kWidth) / kHeight) * glm::vec4(p, 1.0F);
        const float x = (c.x / c.w * 0.5F + 0.5F) * kWidth;
        const float y = (1.0F - (c.y / c.w * 0.5F + 0.5F)) * kHeight;
        return {static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y))};
    }
    gl::Renderer m_renderer;
};

}  // namespace ensil::test

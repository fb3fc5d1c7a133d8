// Where the Sections dock's map and cross-section lie, drawn in the box (gl::Renderer::
// setSectionGuides): a cross-section's curtain seen from straight above is its path, in the
// guides' colour; without guides nothing is drawn there.
#include <gtest/gtest.h>

#include <QColor>

#include "gl/renderer.h"
#include "tests/gl/renderer_fixture.h"

using namespace ensil;

namespace {

bool isGuidePixel(const QColor& c) {
    const glm::vec4 g = gl::Renderer::kSectionGuideColor;
    return std::abs(c.redF() - g.r) < 0.1 && std::abs(c.greenF() - g.g) < 0.1 &&
           std::abs(c.blueF() - g.b) < 0.1;
}

bool guideNear(const QImage& image, QPoint p) {
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            const QPoint q = p + QPoint(dx, dy);
            if (image.rect().contains(q) && isGuidePixel(image.pixelColor(q))) return true;
        }
    }
    return false;
}

}  // namespace

class SectionGuidesRenderTest : public test::RendererFixture {
protected:
    void SetUp() override {
        test::RendererFixture::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        m_renderer.setViewSize(kWidth, kHeight);
        m_renderer.setGrid(data::Grid(data::makeUniformAxis("x", "m", 0.0, 100.0, 11),
                                      data::makeUniformAxis("y", "m", 0.0, 50.0, 6),
                                      data::makeUniformAxis("z", "m", 0.0, 10.0, 3)));
        m_renderer.setBackground({0.0F, 0.0F, 0.0F, 1.0F});
        m_renderer.camera().setProjection(gl::Camera::Projection::Orthographic);
        m_renderer.lookFrom(-90.0F, 90.0F);
    }
    // A place in the box's unit cube, on screen.
    QPoint at(glm::dvec3 unit) const {
        return project(glm::vec3(unit) * m_renderer.frame().boxMax());
    }
};

TEST_F(SectionGuidesRenderTest, ACurtainSeenFromAboveIsItsPath) {
    // A path from (0.2, 0.3) to (0.8, 0.6) across the floor, and the same at the top.
    m_renderer.setSectionGuides(
        {{{0.2, 0.3, 0.0}, {0.8, 0.6, 0.0}}, {{0.2, 0.3, 1.0}, {0.8, 0.6, 1.0}}});
    const QImage with = draw();
    for (const double t : {0.25, 0.5, 0.75}) {
        const glm::dvec3 p{0.2 + 0.6 * t, 0.3 + 0.3 * t, 0.0};
        EXPECT_TRUE(guideNear(with, at(p))) << "along the path at " << t;
    }
    // Away from the path (the floor's middle below it) nothing of the guides' colour.
    EXPECT_FALSE(guideNear(with, at({0.6, 0.2, 0.0})));
    m_renderer.setSectionGuides({});
    const QImage without = draw();
    EXPECT_FALSE(guideNear(without, at({0.5, 0.45, 0.0})));
}

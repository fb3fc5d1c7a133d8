// Antialiasing (METHODS.md section 11): translucent silhouettes are box-filtered over the pixel,
// so a silhouette thinner than a pixel stays an unbroken, fainter ring; the box's edges are
// antialiased wide lines, with pixels between the line's colour and the background's where an
// aliased line has only those two.
#include <QImage>
#include <cmath>
#include <numbers>

#include "tests/gl/sphere_scene.h"

using namespace ensil;
using test::spheres;

namespace {
constexpr glm::vec3 kWhite{1.0F, 1.0F, 1.0F};

int brightness(const QImage& image, int x, int y) {
    const QColor c = image.pixelColor(x, y);
    return std::max({c.red(), c.green(), c.blue()});
}

class AntialiasingTest : public test::SphereSceneTest {
protected:
    void SetUp() override {
        test::SphereSceneTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        show(spheres({m_centre}), {kWhite});
        m_renderer.settings().showMean = false;
        m_renderer.settings().showAxes = false;
    }
    double outlineRadius() {
        const QPoint middle = project(display(m_centre));
        return project(display(m_centre + glm::vec3(8.0F, 0, 0))).x() - middle.x();
    }
    const glm::vec3 m_centre{15.5F, 15.5F, 15.5F};
};
}  // namespace

TEST_F(AntialiasingTest, ASilhouetteThinnerThanAPixelStaysAnUnbrokenRing) {
    m_renderer.settings().mode = gl::RenderMode::ShadedSilhouettes;
    // A band about half a pixel wide at the outline: point-sampled it breaks into dashes (8 of
    // the 360 rays found nothing when the filter was taken out).
    m_renderer.settings().thickness = 0.005F;
    const QImage image = draw();
    const QPoint middle = project(display(m_centre));
    const double radius = outlineRadius();
    // Along every ray from the centre, something of the ring is drawn near the outline.
    int broken = 0;
    for (int step = 0; step < 360; ++step) {
        const double angle = step * std::numbers::pi / 180.0;
        int best = 0;
        for (double r = radius - 3.0; r <= radius + 1.5; r += 0.25) {
            const int x = middle.x() + static_cast<int>(std::lround(r * std::cos(angle)));
            const int y = middle.y() + static_cast<int>(std::lround(r * std::sin(angle)));
            if (image.rect().contains(x, y)) best = std::max(best, brightness(image, x, y));
        }
        if (best < 10) ++broken;
    }
    EXPECT_LE(broken, 4) << "rays that cross no part of the ring";
}

TEST_F(AntialiasingTest, TheBoxEdgesAreSmoothLines) {
    m_renderer.settings().showAxes = true;
    m_renderer.setMeshes(nullptr);
    m_renderer.camera().setAngles(-60.0F, 25.0F);  // slanted edges
    m_renderer.camera().frameBox(m_renderer.frame().boxMin(), m_renderer.frame().boxMax(),
                                 float(kWidth) / kHeight);
    const QImage image = draw();
    int line = 0, between = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const int b = brightness(image, x, y);
            if (b >= 25) ++line;
            if (b >= 25 && b <= 180) ++between;
        }
    }
    ASSERT_GT(line, 200) << "the box is drawn";
    EXPECT_GT(between, line / 3) << "slanted edges blend into the background";
}

// Drawing the scene at a fraction of the frame's size (what the view does while the camera
// moves): the frame is still filled, the scene is drawn smaller, and the picture is the full
// one, only softer; at scale 1 nothing changes.
#include <gtest/gtest.h>

#include "tests/gl/sphere_scene.h"

using namespace ensil;

namespace {
// The rectangle around every pixel that is not the black background.
QRect drawnRectangle(const QImage& image) {
    QRect r;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (image.pixelColor(x, y).value() > 24) r |= QRect(x, y, 1, 1);
        }
    }
    return r;
}

using ResolutionScaleTest = test::TwoSpheresTest;
}  // namespace

TEST_F(ResolutionScaleTest, HalfResolutionFillsTheFrameWithTheSamePicture) {
    m_renderer.settings().thickness = 0.05F;
    const QImage full = draw();
    EXPECT_EQ(m_renderer.sceneSize(), glm::ivec2(kWidth, kHeight));

    m_renderer.setResolutionScale(0.5F);
    const QImage half = draw();
    EXPECT_EQ(m_renderer.sceneSize(), glm::ivec2(kWidth / 2, kHeight / 2));
    ASSERT_EQ(half.size(), full.size());
    QImage black(full.size(), full.format());
    black.fill(Qt::black);
    EXPECT_GT(test::differingFraction(full, black, 16), 0.05) << "silhouettes are drawn";
    // The same shapes in the same places: only edges, a pixel or two wide, differ.
    const double differing = test::differingFraction(full, half, 64);
    EXPECT_GT(differing, 0.0) << "drawn at half resolution, not full";
    EXPECT_LT(differing, 0.05);
    // Scaled up to the whole frame, not drawn into a corner of it: what is drawn spans the
    // same rectangle.
    const QRect drawn = drawnRectangle(full);
    const QRect drawnAtHalf = drawnRectangle(half);
    EXPECT_GT(drawn.width(), kWidth / 4);
    EXPECT_NEAR(drawnAtHalf.left(), drawn.left(), 2);
    EXPECT_NEAR(drawnAtHalf.right(), drawn.right(), 2);
    EXPECT_NEAR(drawnAtHalf.top(), drawn.top(), 2);
    EXPECT_NEAR(drawnAtHalf.bottom(), drawn.bottom(), 2);

    half.save(test::testOutputDir() + "/resolution_scale_half.png");
    full.save(test::testOutputDir() + "/resolution_scale_full.png");

    m_renderer.setResolutionScale(1.0F);
    EXPECT_EQ(test::differingFraction(draw(), full, 0), 0.0) << "scale 1 is the full picture";
}

TEST_F(ResolutionScaleTest, ScaleIsClamped) {
    m_renderer.setResolutionScale(0.01F);
    EXPECT_EQ(m_renderer.resolutionScale(), gl::Renderer::kMinimumResolutionScale);
    m_renderer.setResolutionScale(3.0F);
    EXPECT_EQ(m_renderer.resolutionScale(), 1.0F);
}

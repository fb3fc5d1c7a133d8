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

// Frames below full resolution draw the members from the motion meshes when there are any; at
// full resolution, and for picking, the full meshes always. Motion meshes with nothing in them
// make the difference plain.
TEST_F(ResolutionScaleTest, FramesBelowFullResolutionDrawTheMotionMeshes) {
    m_renderer.settings().thickness = 0.05F;
    m_renderer.settings().showMean = false;
    const auto full = m_renderer.meshes();
    auto empty = std::make_shared<data::MeshSet>();
    empty->members.resize(full->members.size());
    // What a frame at half resolution shows with the full meshes, and with none (the box).
    m_renderer.setResolutionScale(0.5F);
    const QImage withFull = draw();
    m_renderer.setMeshes(empty);
    const QImage withNone = draw();
    ASSERT_GT(test::differingFraction(withFull, withNone, 16), 0.01) << "the members are seen";
    m_renderer.setMeshes(full);
    m_renderer.setResolutionScale(1.0F);
    const QImage still = draw();

    m_renderer.setMotionMeshes(empty);
    m_renderer.setResolutionScale(0.5F);
    EXPECT_EQ(test::differingFraction(draw(), withNone, 0), 0.0)
        << "the motion meshes (nothing) are drawn";
    m_renderer.settings().mode = gl::RenderMode::OpaqueSurfaces;
    EXPECT_NE(m_renderer.pick(kWidth / 2, kHeight / 2).member, -1)
        << "picking answers for the full meshes";
    m_renderer.settings().mode = gl::RenderMode::ShadedSilhouettes;
    m_renderer.setResolutionScale(1.0F);
    EXPECT_EQ(test::differingFraction(draw(), still, 0), 0.0) << "still: the full meshes";

    // Another member count cannot stand for these members: the full meshes are drawn.
    auto fewer = std::make_shared<data::MeshSet>();
    fewer->members.resize(full->members.size() - 1);
    m_renderer.setMotionMeshes(fewer);
    m_renderer.setResolutionScale(0.5F);
    EXPECT_EQ(test::differingFraction(draw(), withFull, 0), 0.0);
    // New meshes drop the old motion meshes.
    m_renderer.setMotionMeshes(empty);
    m_renderer.setMeshes(full);
    EXPECT_EQ(test::differingFraction(draw(), withFull, 0), 0.0);
}

// The warm-up draws a scene of its own through every pass (so the driver compiles its shader
// variants at start-up); what the user sees must come back exactly.
#include <gtest/gtest.h>

#include "tests/gl/sphere_scene.h"

using namespace ensil;

using WarmUpTest = test::TwoSpheresTest;

TEST_F(WarmUpTest, PutsTheSceneBack) {
    m_renderer.settings().mode = gl::RenderMode::Spaghetti;
    m_renderer.settings().thickness = 0.05F;
    const QImage before = draw();
    const auto meshes = m_renderer.meshes();
    const glm::vec3 eye = m_renderer.camera().eye();
    // On the left sphere's silhouette, which picking answers for from the last frame's size.
    const QPoint edge = project(display({4.2F, 15.5F, 15.5F}));
    const int pickedBefore = m_renderer.pick(edge.x(), edge.y()).member;
    ASSERT_EQ(pickedBefore, 0);

    m_renderer.warmUp();

    EXPECT_EQ(m_renderer.meshes(), meshes);
    EXPECT_EQ(m_renderer.settings().mode, gl::RenderMode::Spaghetti);
    EXPECT_EQ(m_renderer.camera().eye(), eye);
    EXPECT_EQ(m_renderer.pick(edge.x(), edge.y()).member, pickedBefore)
        << "picking answers for the last frame before the warm-up";
    EXPECT_EQ(test::differingFraction(draw(), before, 0), 0.0);
}

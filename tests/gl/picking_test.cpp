// Picking: the id pass returns the member under a pixel, the front-most where members overlap,
// and nothing on the background or where a member draws nothing.
#include "tests/gl/sphere_scene.h"

using namespace ensil;
using test::spheres;
using PickingTest = test::SphereSceneTest;

namespace {
constexpr glm::vec3 kRed{1, 0.2F, 0.2F};
constexpr glm::vec3 kBlue{0.2F, 0.3F, 1};
}  // namespace

TEST_F(PickingTest, ReturnsTheMemberWhoseSilhouetteIsUnderThePixel) {
    // Two spheres side by side (x = 9 and x = 22), seen along +y.
    show(spheres({{9, 15.5F, 15.5F}, {22, 15.5F, 15.5F}}), {kRed, kBlue});
    m_renderer.setAppearance({{kRed, true, false, 3}, {kBlue, true, false, 5}});
    m_renderer.settings().showMean = false;
    m_renderer.settings().thickness = 0.1F;
    (void)draw();
    const QPoint leftRim = project(display({9 - 7.9F, 15.5F, 15.5F}));
    const QPoint rightRim = project(display({22 + 7.9F, 15.5F, 15.5F}));
    const gl::PickResult left = m_renderer.pick(leftRim.x(), leftRim.y());
    const gl::PickResult right = m_renderer.pick(rightRim.x(), rightRim.y());
    EXPECT_EQ(left.member, 0);
    EXPECT_EQ(left.cluster, 3);
    EXPECT_EQ(right.member, 1);
    EXPECT_EQ(right.cluster, 5);
    // The faces of both spheres draw no silhouette, and the corner is background.
    const QPoint face = project(display({9, 15.5F, 15.5F}));
    EXPECT_EQ(m_renderer.pick(face.x(), face.y()).member, -1);
    EXPECT_EQ(m_renderer.pick(2, 2).member, -1);
    EXPECT_EQ(m_renderer.pick(2, 2).cluster, -1);
    EXPECT_EQ(m_renderer.pick(-5, 10).member, -1) << "outside the view";
}

TEST_F(PickingTest, TheFrontMostMemberWinsWhateverTheDrawingOrder) {
    // Sphere 0 nearer the camera (smaller y) than sphere 1, both on the view axis, drawn as
    // opaque surfaces; then the same with the members listed the other way round.
    const glm::vec3 nearCentre{15.5F, 12, 15.5F}, farCentre{15.5F, 19, 15.5F};
    show(spheres({nearCentre, farCentre}), {kRed, kBlue});
    m_renderer.settings().showMean = false;
    m_renderer.settings().mode = gl::RenderMode::OpaqueSurfaces;
    (void)draw();
    const QPoint middle = project(display(nearCentre));
    EXPECT_EQ(m_renderer.pick(middle.x(), middle.y()).member, 0);

    show(spheres({farCentre, nearCentre}), {kBlue, kRed});
    m_renderer.settings().showMean = false;
    (void)draw();
    EXPECT_EQ(m_renderer.pick(middle.x(), middle.y()).member, 1);
}

TEST_F(PickingTest, SelectedMembersArePickedOverTheirFaceAndHiddenOnesNever) {
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    show(spheres({centre, centre + glm::vec3(0.5F, 0, 0)}), {kRed, kBlue});
    m_renderer.settings().showMean = false;
    m_renderer.settings().thickness = 0.1F;
    (void)draw();
    const QPoint face = project(display(centre));
    EXPECT_EQ(m_renderer.pick(face.x(), face.y()).member, -1) << "silhouettes only";

    m_renderer.setAppearance({{kRed, true, false}, {kBlue, true, true}});
    (void)draw();
    EXPECT_EQ(m_renderer.pick(face.x(), face.y()).member, 1) << "a selected member is solid";

    m_renderer.setAppearance({{kRed, true, false}, {kBlue, false, true}});
    (void)draw();
    const QPoint rim = project(display(centre + glm::vec3(7.9F, 0, 0)));
    EXPECT_EQ(m_renderer.pick(face.x(), face.y()).member, -1) << "hidden, though selected";
    EXPECT_EQ(m_renderer.pick(rim.x(), rim.y()).member, 0) << "the visible one remains";
}

TEST_F(PickingTest, TheMeanOccludesMembersBehindItButIsNotAMember) {
    // A small member sphere behind the big solid mean, and nothing in front of it.
    show(spheres({{15.5F, 15.5F, 15.5F}, {15.5F, 15.5F, 15.5F}}, {0, -4}), {kRed, kBlue});
    m_renderer.settings().showMean = true;
    m_renderer.settings().meanOpacity = 1.0F;
    m_renderer.settings().mode = gl::RenderMode::OpaqueSurfaces;
    (void)draw();
    const QPoint middle = project(display({15.5F, 15.5F, 15.5F}));
    EXPECT_EQ(m_renderer.pick(middle.x(), middle.y()).member, 0)
        << "member 0 (radius 8) lies in front of the mean (radius 6)";
    m_renderer.setAppearance({{kRed, false, false}, {kBlue, true, false}});
    (void)draw();
    EXPECT_EQ(m_renderer.pick(middle.x(), middle.y()).member, -1)
        << "member 1 (radius 4) lies inside the solid mean";
    // A translucent mean is context: the member inside it is picked through it.
    m_renderer.settings().meanOpacity = 0.3F;
    (void)draw();
    EXPECT_EQ(m_renderer.pick(middle.x(), middle.y()).member, 1);
}

TEST_F(PickingTest, BrushingCollectsTheMembersDrawnInARectangle) {
    show(spheres({{9, 15.5F, 15.5F}, {22, 15.5F, 15.5F}}), {kRed, kBlue});
    m_renderer.settings().showMean = false;
    m_renderer.settings().thickness = 0.1F;
    (void)draw();
    const QPoint leftRim = project(display({9 - 7.9F, 15.5F, 15.5F}));
    const QPoint rightRim = project(display({22 + 7.9F, 15.5F, 15.5F}));
    EXPECT_EQ(m_renderer.membersIn(0, 0, kWidth - 1, kHeight - 1), (std::vector<int>{0, 1}));
    EXPECT_EQ(
        m_renderer.membersIn(leftRim.x() - 4, leftRim.y() - 4, leftRim.x() + 4, leftRim.y() + 4),
        (std::vector<int>{0}));
    EXPECT_EQ(m_renderer.membersIn(rightRim.x() + 4, rightRim.y() + 4, rightRim.x() - 4,
                                   rightRim.y() - 4),
              (std::vector<int>{1}))
        << "corners in any order";
    EXPECT_TRUE(m_renderer.membersIn(0, 0, 3, 3).empty());
}

TEST_F(PickingTest, TheAnimatedMemberIsTheOnlySolidOneEvenWhenHidden) {
    // Two spheres side by side; member 1 selected, member 0 hidden and animated.
    show(spheres({{9, 15.5F, 15.5F}, {22, 15.5F, 15.5F}}), {kRed, kBlue});
    m_renderer.setAppearance({{kRed, false, false, 0}, {kBlue, true, true, 1}});
    m_renderer.settings().showMean = false;
    m_renderer.setAnimatedMember(0);
    (void)draw();
    const QPoint left = project(display({9, 15.5F, 15.5F}));
    const QPoint right = project(display({22, 15.5F, 15.5F}));
    EXPECT_EQ(m_renderer.pick(left.x(), left.y(), 0).member, 0) << "animated: solid face";
    EXPECT_EQ(m_renderer.pick(right.x(), right.y(), 0).member, -1)
        << "the selection is drawn as a silhouette while animating";
    m_renderer.setAnimatedMember(-1);
    (void)draw();
    EXPECT_EQ(m_renderer.pick(left.x(), left.y(), 0).member, -1) << "hidden again";
    EXPECT_EQ(m_renderer.pick(right.x(), right.y(), 0).member, 1) << "selected: solid again";
}

// A pick says where the surface lies: the selected sphere's face, picked at its centre, is
// on the sphere (8 cells from its centre, in display space), nearest the camera; the ray
// through a pixel meets the floor inside the box; the background's far corner misses it.
TEST_F(PickingTest, APickGivesThePointOnTheSurfaceAndWhereItsRayMeetsTheFloor) {
    const glm::vec3 centre{15.5F, 15.5F, 15.5F};
    show(spheres({centre}), {kRed});
    m_renderer.setAppearance({{kRed, true, true, 0}});  // selected: solid, picked over its face
    m_renderer.settings().showMean = false;
    m_renderer.camera().setAngles(-90.0F, 30.0F);
    (void)draw();
    const QPoint middle = project(display(centre));
    const gl::PickResult hit = m_renderer.pick(middle.x(), middle.y());
    ASSERT_EQ(hit.member, 0);
    ASSERT_TRUE(hit.surface.has_value());
    const glm::dvec3 index = m_renderer.frame().displayToIndex(*hit.surface);
    EXPECT_NEAR(glm::length(glm::vec3(index) - centre), 8.0F, 0.3F) << "on the sphere";
    EXPECT_LT(glm::distance(*hit.surface, m_renderer.camera().eye()),
              glm::distance(display(centre), m_renderer.camera().eye()))
        << "its near side";
    // The ray through the pixel of the floor's middle meets the floor there (the sphere in
    // front does not matter to the floor point); it lies on z = 0.
    const QPoint low = project(display({15.5F, 15.5F, 0.0F}));
    const gl::PickResult floor = m_renderer.pick(low.x(), low.y());
    ASSERT_TRUE(floor.floor.has_value());
    EXPECT_NEAR(floor.floor->z, 0.0F, 1e-4F);
    const glm::dvec3 floorIndex = m_renderer.frame().displayToIndex(*floor.floor);
    EXPECT_NEAR(floorIndex.x, 15.5, 0.6);
    EXPECT_NEAR(floorIndex.y, 15.5, 0.6);
}

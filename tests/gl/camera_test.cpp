#include "gl/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

using ensil::gl::Camera;

namespace {
glm::vec3 ndc(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0F);
    return glm::vec3(c) / c.w;
}
}  // namespace

TEST(Camera, FitPutsTheTargetInTheCentreAndTheSphereInView) {
    Camera cam;
    cam.fit({1, 2, 3}, 0.5F);
    const glm::mat4 vp = cam.viewProjection(1.0F);
    const glm::vec3 centre = ndc(vp, {1, 2, 3});
    EXPECT_NEAR(centre.x, 0.0F, 1e-5);
    EXPECT_NEAR(centre.y, 0.0F, 1e-5);
    EXPECT_NEAR(glm::length(cam.eye() - glm::vec3(1, 2, 3)), cam.distance(), 1e-4);
    // Points on the sphere along the camera's up and right stay inside the view.
    const glm::mat4 v = cam.view();
    const glm::vec3 up{v[0][1], v[1][1], v[2][1]};
    const glm::vec3 right{v[0][0], v[1][0], v[2][0]};
    for (const glm::vec3& dir : {up, -up, right, -right}) {
        const glm::vec3 p = ndc(vp, glm::vec3(1, 2, 3) + 0.5F * dir);
        EXPECT_LT(std::abs(p.x), 1.0F);
        EXPECT_LT(std::abs(p.y), 1.0F);
        EXPECT_GT(std::max(std::abs(p.x), std::abs(p.y)), 0.7F)
            << "the sphere should fill the view";
    }
}

TEST(Camera, OrbitTurnsAndElevationIsClamped) {
    Camera cam;
    cam.setAngles(10.0F, 20.0F);
    cam.orbit(-25.0F, 0.0F);  // 0.4 degrees per pixel
    EXPECT_NEAR(cam.azimuth(), 20.0F, 1e-4);
    cam.orbit(0.0F, 1000.0F);
    EXPECT_LE(cam.elevation(), 89.0F);
    cam.setAngles(370.0F, 0.0F);
    EXPECT_NEAR(cam.azimuth(), 10.0F, 1e-4);
}

TEST(Camera, PanMovesTargetAcrossTheViewNotAlongIt) {
    Camera cam;
    cam.fit({0, 0, 0}, 1.0F);
    const glm::vec3 before = cam.target();
    const glm::vec3 viewDir = glm::normalize(before - cam.eye());
    cam.pan(30.0F, -10.0F, 600.0F);
    const glm::vec3 moved = cam.target() - before;
    EXPECT_GT(glm::length(moved), 0.0F);
    EXPECT_NEAR(glm::dot(moved, viewDir), 0.0F, 1e-5);
}

TEST(Camera, ZoomChangesDistanceAndOrthographicKeepsCentre) {
    Camera cam;
    cam.fit({0, 0, 0}, 1.0F);
    const float d = cam.distance();
    cam.zoom(2.0F);
    EXPECT_NEAR(cam.distance(), d / 2.0F, 1e-5);
    cam.setProjection(Camera::Projection::Orthographic);
    const glm::vec3 c = ndc(cam.viewProjection(1.5F), {0, 0, 0});
    EXPECT_NEAR(c.x, 0.0F, 1e-5);
    EXPECT_NEAR(c.y, 0.0F, 1e-5);
    EXPECT_GT(c.z, -1.0F);
    EXPECT_LT(c.z, 1.0F);
}

TEST(Camera, FrameBoxFillsTheViewWithAFlatBoxAndKeepsEveryCornerIn) {
    // A flat atmospheric box, 1 x 0.5 x 0.2, seen from the default angles in a 16:10 view.
    const glm::vec3 lo{0.0F}, hi{1.0F, 0.5F, 0.2F};
    for (const float aspect : {1.6F, 0.6F}) {
        ensil::gl::Camera cam;
        cam.reset(0.5F * (lo + hi), 0.5F * glm::length(hi));
        const float sphereDistance = cam.distance();
        cam.frameBox(lo, hi, aspect, 0.8F);
        float extent = 0.0F;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec4 p = cam.viewProjection(aspect) *
                                glm::vec4(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                                          corner & 4 ? hi.z : lo.z, 1.0F);
            extent = std::max({extent, std::abs(p.x / p.w), std::abs(p.y / p.w)});
        }
        EXPECT_LE(extent, 0.8F + 1e-4F) << "aspect " << aspect;
        EXPECT_GE(extent, 0.79F) << "as near as it can be, aspect " << aspect;
        if (aspect > 1.0F) {
            EXPECT_LT(cam.distance(), 0.8F * sphereDistance) << "nearer than the sphere";
        }
    }
}

// The wheel zooms toward the cursor: a point on the target's plane under a pixel off the
// centre stays under that pixel, in perspective and orthographic views; zooming at the centre
// keeps the target.
TEST(Camera, ZoomTowardKeepsThePointUnderTheCursorInPlace) {
    for (const Camera::Projection projection :
         {Camera::Projection::Perspective, Camera::Projection::Orthographic}) {
        Camera cam;
        cam.setProjection(projection);
        cam.fit({0.5F, 0.5F, 0.1F}, 0.6F);
        const float width = 800.0F, height = 600.0F, aspect = width / height;
        // The world point under pixel (600, 150): on the plane through the target facing the
        // camera, found from the pixel's ray.
        const glm::vec2 pixel{600.0F, 150.0F};
        const glm::vec2 offset = pixel - glm::vec2(width / 2.0F, height / 2.0F);
        const glm::mat4 inverse = glm::inverse(cam.viewProjection(aspect));
        const glm::vec4 ndcPoint{pixel.x / width * 2.0F - 1.0F, 1.0F - pixel.y / height * 2.0F,
                                 0.0F, 1.0F};
        const glm::vec4 nearH = inverse * glm::vec4(glm::vec2(ndcPoint), -1.0F, 1.0F);
        const glm::vec4 farH = inverse * glm::vec4(glm::vec2(ndcPoint), 1.0F, 1.0F);
        const glm::vec3 a = glm::vec3(nearH) / nearH.w, b = glm::vec3(farH) / farH.w;
        const glm::vec3 normal = glm::normalize(cam.eye() - cam.target());
        const float t = glm::dot(cam.target() - a, normal) / glm::dot(b - a, normal);
        const glm::vec3 world = a + t * (b - a);

        cam.zoomToward(1.5F, offset, height);
        const glm::vec3 after = ndc(cam.viewProjection(aspect), world);
        EXPECT_NEAR((after.x * 0.5F + 0.5F) * width, pixel.x, 1.0F);
        EXPECT_NEAR((0.5F - after.y * 0.5F) * height, pixel.y, 1.0F);
    }
    Camera centred;
    centred.fit({1, 2, 3}, 0.5F);
    const glm::vec3 target = centred.target();
    centred.zoomToward(2.0F, {0.0F, 0.0F}, 600.0F);
    EXPECT_NEAR(glm::distance(centred.target(), target), 0.0F, 1e-6F);
}

// The side views (issue 39): looking level and orthographic, a level in the middle of the box
// lies on the screen row of the same level on the box's near edge, so the ticks there read true;
// in perspective they do not.
TEST(Camera, LevelOrthographicViewsPutALevelOnItsTicksRowAtAnyDepth) {
    for (const Camera::Projection projection :
         {Camera::Projection::Orthographic, Camera::Projection::Perspective}) {
        Camera cam;
        cam.setProjection(projection);
        cam.setAngles(-90.0F, 0.0F);  // from the south
        cam.fit({0.5F, 0.5F, 0.1F}, 0.75F);
        const glm::mat4 vp = cam.viewProjection(1.6F);
        const float nearEdge = ndc(vp, {0.0F, 0.0F, 0.17F}).y;
        const float middle = ndc(vp, {0.5F, 0.5F, 0.17F}).y;
        if (projection == Camera::Projection::Orthographic) {
            EXPECT_NEAR(middle, nearEdge, 1e-5F);
        } else {
            EXPECT_GT(std::abs(middle - nearEdge), 0.01F);
        }
    }
}

#include "gl/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <optional>

namespace ensil::gl {
namespace {
constexpr float kMaxElevation = 89.0F;
}  // namespace

void Camera::fit(const glm::vec3& center, float radius) {
    m_target = center;
    m_radius = std::max(radius, 1e-6F);
    // Distance at which the sphere fills the vertical field of view, with a small margin.
    m_distance = 1.1F * m_radius / std::sin(glm::radians(kFieldOfViewDeg * 0.5F));
}

void Camera::reset(const glm::vec3& center, float radius) {
    setAngles(kDefaultAzimuth, kDefaultElevation);
    fit(center, radius);
}

void Camera::frameBox(const glm::vec3& boxMin, const glm::vec3& boxMax, float aspect, float fill,
                      const NdcRegion& region) {
    fit(0.5F * (boxMin + boxMax), 0.5F * glm::length(boxMax - boxMin));
    // The box's corners on screen (NDC): their bounding rectangle, or nothing when one lies
    // behind the eye.
    const auto bounds = [&]() -> std::optional<NdcRegion> {
        const glm::mat4 vp = viewProjection(aspect);
        NdcRegion r{glm::vec2(std::numeric_limits<float>::max()),
                    glm::vec2(-std::numeric_limits<float>::max())};
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec4 p = vp * glm::vec4((corner & 1) ? boxMax.x : boxMin.x,
                                               (corner & 2) ? boxMax.y : boxMin.y,
                                               (corner & 4) ? boxMax.z : boxMin.z, 1.0F);
            if (p.w <= 0.0F) return std::nullopt;
            const glm::vec2 ndc = glm::vec2(p) / p.w;
            r.min = glm::min(r.min, ndc);
            r.max = glm::max(r.max, ndc);
        }
        return r;
    };
    const glm::vec2 room = fill * (region.max - region.min);
    const bool wholeView = region.min == glm::vec2(-1.0F) && region.max == glm::vec2(1.0F);
    // In the whole view the target stays at the box's centre, every corner within `fill`. In a
    // region the box's size on screen hardly depends on where it is: the distance is chosen
    // for the size, then the box is moved into the region.
    const auto fits = [&] {
        const std::optional<NdcRegion> b = bounds();
        if (!b) return false;
        if (wholeView) {
            const glm::vec2 reach = glm::max(glm::abs(b->min), glm::abs(b->max));
            return reach.x <= fill && reach.y <= fill;
        }
        return b->max.x - b->min.x <= room.x && b->max.y - b->min.y <= room.y;
    };
    // Start from the bounding sphere's distance (moving back when a narrow viewport needs it),
    // then bisect towards the box.
    float far = m_distance;
    for (int step = 0; step < 20 && !fits(); ++step) m_distance = far *= 1.5F;
    float near = 0.05F * far;
    for (int step = 0; step < 30; ++step) {
        m_distance = 0.5F * (near + far);
        (fits() ? far : near) = m_distance;
    }
    m_distance = far;
    // Centre the box's rectangle on the region's centre: pan() in units of half the view's
    // height moves the scene by NDC units (x scaled by the aspect). A few rounds settle the
    // small change a perspective view makes as the box moves.
    const glm::vec2 centre = 0.5F * (region.min + region.max);
    for (int round = 0; round < 4 && !wholeView; ++round) {
        const std::optional<NdcRegion> b = bounds();
        if (!b) break;
        const glm::vec2 shift = centre - 0.5F * (b->min + b->max);
        if (glm::length(shift) < 1e-5F) break;
        pan(shift.x * aspect, -shift.y, 2.0F);
    }
}

void Camera::frameBox(const glm::vec3& boxMin, const glm::vec3& boxMax, float aspect, float fill) {
    frameBox(boxMin, boxMax, aspect, fill, NdcRegion{});
}

void Camera::setAngles(float azimuthDeg, float elevationDeg) {
    m_azimuth = std::remainder(azimuthDeg, 360.0F);
    m_elevation = std::clamp(elevationDeg, -kMaxElevation, kMaxElevation);
}

void Camera::orbit(float dxPixels, float dyPixels, float degreesPerPixel) {
    setAngles(m_azimuth - dxPixels * degreesPerPixel, m_elevation + dyPixels * degreesPerPixel);
}

void Camera::pan(float dxPixels, float dyPixels, float viewportHeight) {
    // World units per pixel at the target's depth, so the point under the mouse follows it.
    const float visibleHeight = 2.0F * m_distance * std::tan(glm::radians(kFieldOfViewDeg * 0.5F));
    const float scale = visibleHeight / std::max(viewportHeight, 1.0F);
    const glm::mat4 v = view();
    const glm::vec3 right{v[0][0], v[1][0], v[2][0]};
    const glm::vec3 up{v[0][1], v[1][1], v[2][1]};
    m_target += (-dxPixels * right + dyPixels * up) * scale;
}

void Camera::zoom(float factor) {
    m_distance =
        std::clamp(m_distance / std::max(factor, 1e-3F), 1e-3F * m_radius, 100.0F * m_radius);
}

void Camera::zoomToward(float factor, glm::vec2 offset, float viewportHeight) {
    const float before = m_distance;
    zoom(factor);
    // At the new scale the point under the cursor sits offset * actual pixels from the
    // centre; the scene moves back by the difference.
    const float actual = before / m_distance;
    pan(offset.x * (1.0F - actual), offset.y * (1.0F - actual), viewportHeight);
}

glm::vec3 Camera::eye() const {
    const float az = glm::radians(m_azimuth);
    const float el = glm::radians(m_elevation);
    const glm::vec3 dir{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
    return m_target + m_distance * dir;
}

glm::mat4 Camera::view() const { return glm::lookAt(eye(), m_target, glm::vec3(0, 0, 1)); }

glm::mat4 Camera::projectionMatrix(float aspect) const {
    const float nearPlane = std::max(m_distance - 4.0F * m_radius, m_distance * 1e-3F);
    const float farPlane = m_distance + 4.0F * m_radius;
    if (m_projection == Projection::Orthographic) {
        const float h = m_distance * std::tan(glm::radians(kFieldOfViewDeg * 0.5F));
        return glm::ortho(-h * aspect, h * aspect, -h, h, nearPlane, farPlane);
    }
    return glm::perspective(glm::radians(kFieldOfViewDeg), aspect, nearPlane, farPlane);
}

}  // namespace ensil::gl

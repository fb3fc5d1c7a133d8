// An orbit camera around a target point: azimuth and elevation in degrees, a distance, and a
// perspective or orthographic projection. Z is up. A value type; GUI thread in practice.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ensil::gl {

class Camera {
public:
    enum class Projection { Perspective, Orthographic };

    // Frames a sphere of the given radius around center, looking from the current angles.
    void fit(const glm::vec3& center, float radius);
    // Back to the default angles, then fit.
    void reset(const glm::vec3& center, float radius);
    // A rectangle of the view in normalised device coordinates, (-1, -1) to (1, 1) whole.
    struct NdcRegion {
        glm::vec2 min{-1.0F};
        glm::vec2 max{1.0F};
    };
    // From the current angles, the nearest distance at which the box's corners span at most
    // `fill` of the region's width and height, for a viewport of this aspect ratio, with the
    // box centred in the region: a flat atmospheric box fills the view instead of floating
    // inside its bounding sphere, and a region short of the whole view keeps room for panels.
    void frameBox(const glm::vec3& boxMin, const glm::vec3& boxMax, float aspect, float fill,
                  const NdcRegion& region);
    void frameBox(const glm::vec3& boxMin, const glm::vec3& boxMax, float aspect,
                  float fill = 0.8F);

    // Mouse gestures, in pixels of a viewport of the given height.
    // Turns by `degreesPerPixel` for each pixel dragged (the view passes 180 over its width,
    // so a drag across it turns half way round).
    void orbit(float dxPixels, float dyPixels, float degreesPerPixel = 0.4F);
    void pan(float dxPixels, float dyPixels, float viewportHeight);
    void zoom(float factor);  // > 1 moves closer
    // Zooms so the point under the cursor stays under it (a map tool's wheel): `offset` is
    // the cursor's position from the view's centre in pixels, y down.
    void zoomToward(float factor, glm::vec2 offset, float viewportHeight);

    void setAngles(float azimuthDeg, float elevationDeg);
    void setProjection(Projection p) { m_projection = p; }
    // Restores a saved view (after fit, which sets the depth range for the scene).
    void setTarget(const glm::vec3& target) { m_target = target; }
    void setDistance(float distance) { m_distance = distance; }

    [[nodiscard]] float azimuth() const { return m_azimuth; }
    [[nodiscard]] float elevation() const { return m_elevation; }
    [[nodiscard]] float distance() const { return m_distance; }
    [[nodiscard]] glm::vec3 target() const { return m_target; }
    [[nodiscard]] Projection projection() const { return m_projection; }
    [[nodiscard]] glm::vec3 eye() const;
    [[nodiscard]] glm::mat4 view() const;
    [[nodiscard]] glm::mat4 projectionMatrix(float aspect) const;
    [[nodiscard]] glm::mat4 viewProjection(float aspect) const {
        return projectionMatrix(aspect) * view();
    }

    [[nodiscard]] bool operator==(const Camera&) const = default;

    static constexpr float kFieldOfViewDeg = 30.0F;
    static constexpr float kDefaultAzimuth = -75.0F;  // from the south, east to the right
    static constexpr float kDefaultElevation = 30.0F;

private:
    glm::vec3 m_target{0.5F};
    float m_distance = 3.0F;
    float m_radius = 1.0F;
    float m_azimuth = kDefaultAzimuth;
    float m_elevation = kDefaultElevation;
    Projection m_projection = Projection::Perspective;
};

}  // namespace ensil::gl

// The rotated-pole transformation written out with vectors, independent of PROJ, for tests to
// check ensil's PROJ-based one against: the rotated frame's north pole is the geographic point
// (poleLon, poleLat) and its origin (rotated 0, 0) lies 90 degrees from that pole along the
// great circle through the geographic north pole, beyond it (CF rotated_latitude_longitude
// with north_pole_grid_longitude 0).
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <numbers>

namespace ensil::test {

class RotatedPole {
public:
    RotatedPole(double poleLon, double poleLat)
        : m_z(unit(poleLon, poleLat)),
          m_x(unit(poleLon + 180.0, 90.0 - poleLat)),
          m_y(glm::cross(m_z, m_x)) {}

    [[nodiscard]] glm::dvec2 toRotated(glm::dvec2 lonLat) const {
        const glm::dvec3 p = unit(lonLat.x, lonLat.y);
        return {degrees(std::atan2(glm::dot(p, m_y), glm::dot(p, m_x))),
                degrees(std::asin(glm::dot(p, m_z)))};
    }
    [[nodiscard]] glm::dvec2 toGeographic(glm::dvec2 rotated) const {
        const double lon = radians(rotated.x);
        const double lat = radians(rotated.y);
        const glm::dvec3 p = std::cos(lat) * std::cos(lon) * m_x +
                             std::cos(lat) * std::sin(lon) * m_y + std::sin(lat) * m_z;
        return {degrees(std::atan2(p.y, p.x)), degrees(std::asin(p.z))};
    }

private:
    static double radians(double d) { return d * std::numbers::pi / 180.0; }
    static double degrees(double r) { return r * 180.0 / std::numbers::pi; }
    static glm::dvec3 unit(double lon, double lat) {
        return {std::cos(radians(lat)) * std::cos(radians(lon)),
                std::cos(radians(lat)) * std::sin(radians(lon)), std::sin(radians(lat))};
    }
    glm::dvec3 m_z, m_x, m_y;
};

}  // namespace ensil::test

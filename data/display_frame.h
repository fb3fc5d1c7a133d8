// Maps data coordinates (longitude, latitude, pressure, metres, grid indices...) into the
// display space the renderer draws in. Horizontal axes keep their true proportions, scaled so
// the longer one spans 1. The vertical axis is mapped to a sensible thickness: when its units
// differ from the horizontal ones (an atmosphere in hPa over a map in degrees), the box is 0.2
// units high before exaggeration, because true proportions would make it a sheet of paper;
// pressure axes are drawn as the user chooses (VerticalAxis): through log-pressure by default,
// so levels sit at their approximate heights, linearly in pressure, or at the heights the
// standard atmosphere gives them; low pressure on top. A value type; any thread.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "data/grid.h"

namespace ensil::data {

// How a pressure axis is drawn (any other vertical axis is drawn linearly in its coordinate):
// log-pressure (about height, the scale height's), linear pressure (the mass of the atmosphere:
// the troposphere takes most of the box), or the ICAO standard atmosphere's heights
// (data/vertical_scale.h; true heights above 11 km too). In the setting table's order.
enum class VerticalAxis { LogPressure, Pressure, StandardHeight };

class DisplayFrame {
public:
    DisplayFrame() = default;
    DisplayFrame(const Grid& grid, float verticalExaggeration,
                 VerticalAxis verticalAxis = VerticalAxis::LogPressure);

    [[nodiscard]] glm::vec3 boxMin() const { return {0.0F, 0.0F, 0.0F}; }
    [[nodiscard]] glm::vec3 boxMax() const { return m_size; }
    [[nodiscard]] glm::vec3 center() const { return 0.5F * m_size; }
    [[nodiscard]] float verticalExaggeration() const { return m_exaggeration; }
    // Whether the vertical axis is drawn through log-pressure.
    [[nodiscard]] bool logPressure() const {
        return m_pressureAxis && m_vertical == VerticalAxis::LogPressure;
    }
    // The choice asked for, and whether it applies (the vertical axis is a pressure's).
    [[nodiscard]] VerticalAxis verticalAxis() const { return m_vertical; }
    [[nodiscard]] bool pressureAxis() const { return m_pressureAxis; }

    // A point given in the grid's axis coordinates, in display space.
    [[nodiscard]] glm::vec3 toDisplay(const glm::dvec3& dataPoint) const;
    // A point given in (fractional) grid indices, in display space.
    [[nodiscard]] glm::vec3 indexToDisplay(const glm::vec3& index) const;
    // The (fractional) grid index of a display-space point, clamped to the grid: the inverse
    // of indexToDisplay, for what lies under the cursor.
    [[nodiscard]] glm::dvec3 displayToIndex(const glm::vec3& display) const;
    // The display coordinate of every grid index along one axis (0 = x, 1 = y, 2 = z): the
    // mapping is separable, so three such tables describe it completely.
    [[nodiscard]] std::vector<double> axisTable(int axis) const;

private:
    [[nodiscard]] double verticalFraction(double z) const;
    // The pressure at a fraction of the box's height: verticalFraction's inverse.
    [[nodiscard]] double pressureAt(double fraction) const;
    // What a pressure axis is drawn linearly in: log p, -p or the standard atmosphere's height.
    [[nodiscard]] double drawnPressure(double p) const;

    Grid m_grid;
    glm::vec3 m_size{1.0F};
    float m_exaggeration = 1.0F;
    VerticalAxis m_vertical = VerticalAxis::LogPressure;
    bool m_pressureAxis = false;  // a pressure axis of positive values: m_vertical applies
    double m_hectopascals = 1.0;  // per unit of the pressure axis
};

}  // namespace ensil::data

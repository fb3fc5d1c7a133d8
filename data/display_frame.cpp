#include "data/display_frame.h"

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>

#include "data/vertical_scale.h"

namespace ensil::data {
namespace {
constexpr float kAtmosphereThickness = 0.2F;

}  // namespace

DisplayFrame::DisplayFrame(const Grid& grid, float verticalExaggeration, VerticalAxis verticalAxis)
    : m_grid(grid), m_exaggeration(verticalExaggeration), m_vertical(verticalAxis) {
    const double sx = grid.x().maxValue() - grid.x().minValue();
    const double sy = grid.y().maxValue() - grid.y().minValue();
    const double longest = std::max(sx, sy);
    m_size.x = static_cast<float>(sx / longest);
    m_size.y = static_cast<float>(sy / longest);
    m_pressureAxis = isPressureUnit(grid.z().units) && grid.z().minValue() > 0.0;
    if (m_pressureAxis) m_hectopascals = hectopascalsPer(grid.z().units);
    const bool sameUnits = grid.z().units == grid.x().units && grid.x().units == grid.y().units;
    const double sz = grid.z().maxValue() - grid.z().minValue();
    const float natural =
        sameUnits && !m_pressureAxis ? static_cast<float>(sz / longest) : kAtmosphereThickness;
    m_size.z = natural * verticalExaggeration;
}

double DisplayFrame::drawnPressure(double p) const {
    switch (m_vertical) {
        case VerticalAxis::Pressure:
            return -p;
        case VerticalAxis::StandardHeight:
            return standardAtmosphereHeight(p * m_hectopascals);
        case VerticalAxis::LogPressure:
            break;
    }
    return -std::log(p);
}

double DisplayFrame::pressureAt(double fraction) const {
    const Axis& axis = m_grid.z();
    const double bottom = axis.maxValue(), top = axis.minValue();
    if (m_vertical == VerticalAxis::LogPressure) {
        return std::exp(std::log(bottom) - fraction * (std::log(bottom) - std::log(top)));
    }
    if (m_vertical == VerticalAxis::Pressure) return bottom - fraction * (bottom - top);
    // The standard atmosphere's height has no closed inverse over its layers: bisection, to a
    // millionth of the box (heights rise as pressure falls).
    const double low = drawnPressure(bottom), high = drawnPressure(top);
    const double wanted = low + fraction * (high - low);
    double below = top, above = bottom;  // pressures bracketing it
    for (int i = 0; i < 60; ++i) {
        const double middle = 0.5 * (below + above);
        (drawnPressure(middle) > wanted ? below : above) = middle;
    }
    return 0.5 * (below + above);
}

double DisplayFrame::verticalFraction(double z) const {
    const Axis& axis = m_grid.z();
    double t = 0.0;
    if (m_pressureAxis) {
        const double bottom = drawnPressure(axis.maxValue());
        t = (drawnPressure(z) - bottom) / (drawnPressure(axis.minValue()) - bottom);
    } else {
        t = (z - axis.minValue()) / (axis.maxValue() - axis.minValue());
        if (!axis.positiveUp) t = 1.0 - t;
    }
    return t;
}

glm::vec3 DisplayFrame::toDisplay(const glm::dvec3& p) const {
    const Axis& ax = m_grid.x();
    const Axis& ay = m_grid.y();
    // Horizontal axes may run either way; display always grows with the coordinate.
    const double fx = (p.x - ax.minValue()) / (ax.maxValue() - ax.minValue());
    const double fy = (p.y - ay.minValue()) / (ay.maxValue() - ay.minValue());
    return {static_cast<float>(fx) * m_size.x, static_cast<float>(fy) * m_size.y,
            static_cast<float>(verticalFraction(p.z)) * m_size.z};
}

std::vector<double> DisplayFrame::axisTable(int axis) const {
    const std::size_t n = m_grid.axis(axis).size();
    std::vector<double> table(n);
    for (std::size_t i = 0; i < n; ++i) {
        glm::vec3 index{0.0F};
        index[axis] = static_cast<float>(i);
        table[i] = indexToDisplay(index)[axis];
    }
    return table;
}

glm::vec3 DisplayFrame::indexToDisplay(const glm::vec3& index) const {
    return toDisplay(
        {m_grid.x().valueAt(index.x), m_grid.y().valueAt(index.y), m_grid.z().valueAt(index.z)});
}

glm::dvec3 DisplayFrame::displayToIndex(const glm::vec3& display) const {
    glm::dvec3 index{0.0};
    for (int a = 0; a < 3; ++a) {
        const Axis& axis = m_grid.axis(a);
        const double t = std::clamp(double(display[a]) / double(m_size[a]), 0.0, 1.0);
        // The coordinate that toDisplay puts there: the inverse of its per-axis mapping.
        double coordinate = axis.minValue() + t * (axis.maxValue() - axis.minValue());
        if (a == 2 && m_pressureAxis) {
            coordinate = pressureAt(t);
        } else if (a == 2 && !axis.positiveUp) {
            coordinate = axis.maxValue() - t * (axis.maxValue() - axis.minValue());
        }
        // Then the fractional index of that coordinate along the (monotonic) axis.
        const std::vector<double>& v = axis.values;
        const bool rising = v.back() >= v.front();
        std::size_t i = 0;
        while (i + 2 < v.size() && (rising ? v[i + 1] < coordinate : v[i + 1] > coordinate)) ++i;
        const double span = v[i + 1] - v[i];
        const double f = span != 0.0 ? (coordinate - v[i]) / span : 0.0;
        index[a] = std::clamp(static_cast<double>(i) + f, 0.0, static_cast<double>(v.size() - 1));
    }
    return index;
}

}  // namespace ensil::data

#include "data/grid.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <string_view>

#include "data/ascii_case.h"
#include "data/error.h"

namespace ensil::data {

double Axis::minValue() const { return std::min(values.front(), values.back()); }
double Axis::maxValue() const { return std::max(values.front(), values.back()); }

bool Axis::isUniform() const {
    if (values.size() < 3) return true;
    const double step = values[1] - values[0];
    // Coordinates are often stored as float; near 360 degrees a float resolves only 3e-5, which
    // is half a percent of a 0.0135-degree step. Uneven axes (pressure levels) differ by far more.
    const double tolerance = 1e-2 * std::abs(step);
    for (std::size_t i = 2; i < values.size(); ++i) {
        if (std::abs((values[i] - values[i - 1]) - step) > tolerance) return false;
    }
    return true;
}

double Axis::valueAt(double index) const {
    const double t = std::clamp(index, 0.0, static_cast<double>(values.size() - 1));
    const auto i = std::min(static_cast<std::size_t>(t), values.size() - 2);
    const double f = t - static_cast<double>(i);
    return values[i] + f * (values[i + 1] - values[i]);
}

double Axis::indexOf(double value) const {
    if (!std::isfinite(value) || value < minValue() || value > maxValue()) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    // The axis is strictly monotonic: the first step whose far end passes the value holds it.
    const bool increasing = values.back() > values.front();
    for (std::size_t i = 0; i + 1 < values.size(); ++i) {
        const double a = values[i], b = values[i + 1];
        if (increasing ? value <= b : value >= b)
            return static_cast<double>(i) + (value - a) / (b - a);
    }
    return static_cast<double>(values.size() - 1);
}

bool isPressureUnit(const std::string& units) { return hectopascalsPer(units) > 0.0; }

double hectopascalsPer(const std::string& units) {
    const std::string u = asciiLower(units);
    if (u == "pa") return 0.01;
    if (u == "hpa" || u == "mbar" || u == "millibar" || u == "millibars" || u == "mb") return 1.0;
    if (u == "kpa") return 10.0;
    if (u == "bar") return 1000.0;
    if (u == "atm") return 1013.25;
    return 0.0;
}

double metresPer(const std::string& units) {
    const std::string u = asciiLower(units);
    if (u == "m" || u == "meters" || u == "metres" || u == "meter" || u == "metre") return 1.0;
    if (u == "km" || u == "kilometers" || u == "kilometres") return 1000.0;
    return 0.0;
}

namespace {
template <std::size_t N>
bool oneOf(const std::string& value, const std::array<std::string_view, N>& options) {
    return std::find(options.begin(), options.end(), value) != options.end();
}
}  // namespace

bool isLongitudeAxis(const Axis& axis) {
    const std::string units = asciiLower(axis.units);
    const std::string name = asciiLower(axis.name);
    return axis.standardName == "longitude" ||
           oneOf(units, std::array<std::string_view, 6>{"degrees_east", "degree_east", "degree_e",
                                                        "degrees_e", "degreee", "degreese"}) ||
           (units.starts_with("degree") &&
            oneOf(name, std::array<std::string_view, 3>{"lon", "longitude", "long"}));
}

bool isLatitudeAxis(const Axis& axis) {
    const std::string units = asciiLower(axis.units);
    const std::string name = asciiLower(axis.name);
    return axis.standardName == "latitude" ||
           oneOf(units, std::array<std::string_view, 6>{"degrees_north", "degree_north", "degree_n",
                                                        "degrees_n", "degreen", "degreesn"}) ||
           (units.starts_with("degree") &&
            oneOf(name, std::array<std::string_view, 2>{"lat", "latitude"}));
}

Axis makeUniformAxis(std::string name, std::string units, double first, double last,
                     std::size_t n) {
    Axis axis;
    axis.name = std::move(name);
    axis.units = std::move(units);
    axis.values.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double t = n > 1 ? static_cast<double>(i) / static_cast<double>(n - 1) : 0.0;
        axis.values[i] = first + t * (last - first);
    }
    return axis;
}

namespace {
void checkAxis(const Axis& axis) {
    if (axis.values.size() < 2) {
        throw Error(ErrorKind::InvalidArgument,
                    "axis '" + axis.name + "' has " + std::to_string(axis.values.size()) +
                        " value(s): a 3D grid needs at least 2 points along every axis");
    }
    const bool increasing = axis.values[1] > axis.values[0];
    for (std::size_t i = 1; i < axis.values.size(); ++i) {
        const double step = axis.values[i] - axis.values[i - 1];
        if (!std::isfinite(axis.values[i]) || (increasing ? step <= 0 : step >= 0)) {
            throw Error(ErrorKind::InvalidArgument,
                        "axis '" + axis.name + "' is not strictly monotonic at index " +
                            std::to_string(i) + ": coordinates must increase or decrease");
        }
    }
}
}  // namespace

Grid::Grid(Axis x, Axis y, Axis z) : m_axes{std::move(x), std::move(y), std::move(z)} {
    for (const Axis& axis : m_axes) checkAxis(axis);
}

bool Grid::sameShapeAndCoordinates(const Grid& other) const {
    for (std::size_t a = 0; a < 3; ++a) {
        const auto& mine = m_axes[a].values;
        const auto& theirs = other.m_axes[a].values;
        if (mine.size() != theirs.size()) return false;
        for (std::size_t i = 0; i < mine.size(); ++i) {
            const double scale = std::max(1.0, std::abs(mine[i]));
            if (std::abs(mine[i] - theirs[i]) > 1e-6 * scale) return false;
        }
    }
    return true;
}

std::optional<std::string> fewLevelsWarning(const Grid& grid) {
    const std::size_t levels = grid.nz();
    if (levels >= kFewLevels) return std::nullopt;
    return "only " + std::to_string(levels) + " levels along " + grid.z().name +
           ": every isosurface is at most " + std::to_string(levels - 1) +
           (levels == 2 ? " cell" : " cells") +
           " thick, so its silhouettes show a thin sheet rather than a shape; data with "
           "more levels shows more";
}

}  // namespace ensil::data

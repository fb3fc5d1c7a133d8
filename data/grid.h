// A rectilinear 3D grid: three independent, strictly monotonic coordinate axes (uneven spacing
// allowed, e.g. pressure levels). Values on the grid are stored x-fastest:
// index = x + nx * (y + ny * z), the C order of a NetCDF variable (z, y, x).
// Immutable after construction; safe to share between threads.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ensil::data {

struct Axis {
    std::string name;            // e.g. "lon", "plev"
    std::string units;           // e.g. "degrees_east", "hPa"
    std::string standardName;    // CF standard_name, may be empty
    std::vector<double> values;  // strictly increasing or strictly decreasing
    bool positiveUp = true;      // false for pressure-like axes (CF positive = "down")

    [[nodiscard]] std::size_t size() const { return values.size(); }
    [[nodiscard]] double front() const { return values.front(); }
    [[nodiscard]] double back() const { return values.back(); }
    [[nodiscard]] double minValue() const;
    [[nodiscard]] double maxValue() const;
    // The coordinate at a fractional index, linear between grid points, clamped to the axis.
    [[nodiscard]] double valueAt(double index) const;
    // The fractional index of a coordinate, linear between grid points (the inverse of
    // valueAt); NaN outside the axis or for a non-finite value.
    [[nodiscard]] double indexOf(double value) const;
    // True when all steps are equal within 1 % of a step (float-stored coordinates jitter).
    [[nodiscard]] bool isUniform() const;
};

// Builds an axis of n evenly spaced values from first to last (inclusive).
Axis makeUniformAxis(std::string name, std::string units, double first, double last, std::size_t n);

// True for units that name a pressure (Pa, hPa, mbar, millibars, ...), case-insensitive.
bool isPressureUnit(const std::string& units);
// hPa per unit of a pressure, metres per unit of a length (m, km, metres...); 0 for units that
// are not one ensil knows. Case-insensitive.
double hectopascalsPer(const std::string& units);
double metresPer(const std::string& units);

// CF: a longitude axis has standard_name longitude or units degrees_east (and spellings); plain
// "degrees" counts when the axis is named like one (lon, longitude, long). A rotated pole's
// grid_longitude is not one. Latitude likewise (degrees_north; lat, latitude).
bool isLongitudeAxis(const Axis& axis);
bool isLatitudeAxis(const Axis& axis);

class Grid {
public:
    Grid() = default;
    // Throws Error(InvalidArgument) unless every axis has at least 2 strictly monotonic values.
    Grid(Axis x, Axis y, Axis z);

    [[nodiscard]] const Axis& x() const { return m_axes[0]; }
    [[nodiscard]] const Axis& y() const { return m_axes[1]; }
    [[nodiscard]] const Axis& z() const { return m_axes[2]; }
    [[nodiscard]] const Axis& axis(int i) const { return m_axes.at(static_cast<std::size_t>(i)); }

    [[nodiscard]] std::size_t nx() const { return m_axes[0].size(); }
    [[nodiscard]] std::size_t ny() const { return m_axes[1].size(); }
    [[nodiscard]] std::size_t nz() const { return m_axes[2].size(); }
    [[nodiscard]] std::size_t pointCount() const { return nx() * ny() * nz(); }
    [[nodiscard]] std::size_t index(std::size_t i, std::size_t j, std::size_t k) const {
        return i + nx() * (j + ny() * k);
    }
    [[nodiscard]] bool sameShapeAndCoordinates(const Grid& other) const;

private:
    std::array<Axis, 3> m_axes;
};

// Below this many vertical levels an isosurface is at most a couple of cells thick: what a
// user should be told when such data opens.
inline constexpr std::size_t kFewLevels = 4;
// "only 2 levels (plev): ..." for a grid with fewer than kFewLevels vertical levels; none
// otherwise.
std::optional<std::string> fewLevelsWarning(const Grid& grid);

}  // namespace ensil::data

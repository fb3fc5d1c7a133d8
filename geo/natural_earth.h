// Natural Earth's coastlines and country borders (public domain; resources/map/README.md), at
// 1:110m and 1:50m, embedded in the library and read once. Longitudes in [-180, 180] and
// latitudes in degrees. Any thread.
#pragma once

#include <glm/vec2.hpp>
#include <vector>

namespace ensil::geo {

enum class MapFeature { Coastlines, Borders };
// Natural Earth's scales: 1:110m for continents and the globe, 1:50m for a region.
enum class MapScale { Small110m, Medium50m };

// A line of longitude/latitude points, degrees.
using LonLatLine = std::vector<glm::dvec2>;

// The lines of one feature at one scale. Read from the embedded file at the first call; a
// damaged file (which the build embeds, so only a broken build) gives no lines.
const std::vector<LonLatLine>& naturalEarthLines(MapFeature feature, MapScale scale);

// Domains wider than this (degrees, the larger of the longitude and latitude extents) get the
// 1:110m lines; a region gets 1:50m, whose detail would be noise on a hemisphere.
inline constexpr double kRegionalExtentDegrees = 60.0;
MapScale scaleForExtent(double extentDegrees);

}  // namespace ensil::geo

// The map lines on the floor of a grid: Natural Earth coastlines and borders, and for a
// rotated or projected grid a graticule of true meridians and parallels, transformed into the
// grid's own x, y (axis units) and clipped to its horizontal extent. Computed once per grid
// (tens of milliseconds for the 1:50m lines); any thread.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "data/grid.h"
#include "geo/map_projection.h"

namespace ensil::geo {

enum class MapLineKind { Coastline, Border, Graticule };

struct MapLine {
    MapLineKind kind = MapLineKind::Coastline;
    std::vector<glm::dvec2> points;  // grid axis coordinates, inside the grid's x-y rectangle
    // A graticule line's true longitude or latitude ("10°W", "54°N"), written where it
    // enters the grid; empty for coastlines and borders.
    std::string label;
};

// Every coastline, border and (rotated or projected grids only: a longitude/latitude grid's
// axes already read in degrees) graticule line over the grid; none without geography.
std::vector<MapLine> mapLinesFor(const data::Grid& grid, const MapProjection& projection);
// The same, through the grid's own mapping (MapProjection::forGrid).
std::vector<MapLine> mapLinesFor(const data::Grid& grid, const data::GridMapping& mapping);

// Clips a polyline (grid coordinates, NaN for points with none) to the rectangle [lo, hi],
// appending the pieces inside to `out`. The line breaks at a NaN and across any step longer
// than `longestStep`: a step that long is a wrap around the globe or a jump across a
// projection's edge, not a piece of coast.
void clipToRectangle(const std::vector<glm::dvec2>& line, glm::dvec2 lo, glm::dvec2 hi,
                     double longestStep, std::vector<std::vector<glm::dvec2>>& out);

}  // namespace ensil::geo

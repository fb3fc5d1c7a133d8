// The longitudes and latitudes a grid covers, in true degrees, whatever its projection: what
// `ensil info` reports and what chooses the coastlines' scale and the graticule's spacing.
#pragma once

#include <optional>

#include "data/grid.h"
#include "geo/map_projection.h"

namespace ensil::geo {

struct LonLatBounds {
    double lonMin = 0.0;  // a domain across the antimeridian has lonMax > 180
    double lonMax = 0.0;
    double latMin = 0.0;
    double latMax = 0.0;
    [[nodiscard]] double extent() const;  // the larger of the two spans, degrees
};

// Sampled along the grid's edges (a projection maps the rectangle's inside within its edges'
// longitudes unless a pole lies inside, which is checked); nullopt without geography.
std::optional<LonLatBounds> lonLatBounds(const data::Grid& grid, const MapProjection& projection);

}  // namespace ensil::geo

#include "geo/domain_bounds.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ensil::geo {
namespace {

// Points per edge: a rotated or conic grid's edges are curves in longitude/latitude, and 256
// samples put each within a few metres of its true extreme.
constexpr int kSamplesPerEdge = 256;

std::vector<glm::dvec2> edgePoints(const data::Grid& grid) {
    const double x0 = grid.x().minValue();
    const double x1 = grid.x().maxValue();
    const double y0 = grid.y().minValue();
    const double y1 = grid.y().maxValue();
    std::vector<glm::dvec2> points;
    points.reserve(4 * kSamplesPerEdge);
    for (int i = 0; i < kSamplesPerEdge; ++i) {
        const double t = static_cast<double>(i) / (kSamplesPerEdge - 1);
        points.emplace_back(x0 + t * (x1 - x0), y0);
        points.emplace_back(x0 + t * (x1 - x0), y1);
        points.emplace_back(x0, y0 + t * (y1 - y0));
        points.emplace_back(x1, y0 + t * (y1 - y0));
    }
    return points;
}

bool containsPole(const data::Grid& grid, const MapProjection& projection, double latitude) {
    std::vector<glm::dvec2> pole{{0.0, latitude}};
    projection.toGrid(pole);
    const glm::dvec2 p = pole.front();
    return std::isfinite(p.x) && p.x >= grid.x().minValue() && p.x <= grid.x().maxValue() &&
           p.y >= grid.y().minValue() && p.y <= grid.y().maxValue();
}

}  // namespace

double LonLatBounds::extent() const { return std::max(lonMax - lonMin, latMax - latMin); }

std::optional<LonLatBounds> lonLatBounds(const data::Grid& grid, const MapProjection& projection) {
    if (!projection.hasGeography()) return std::nullopt;
    if (projection.kind() == MapProjection::Kind::LonLat) {
        return LonLatBounds{grid.x().minValue(), grid.x().maxValue(), grid.y().minValue(),
                            grid.y().maxValue()};
    }
    std::vector<glm::dvec2> points = edgePoints(grid);
    projection.toLonLat(points);
    std::vector<double> lons;
    LonLatBounds b{0.0, 0.0, 90.0, -90.0};
    for (const glm::dvec2& p : points) {
        if (!std::isfinite(p.x)) continue;
        lons.push_back(std::remainder(p.x, 360.0));  // [-180, 180]
        b.latMin = std::min(b.latMin, p.y);
        b.latMax = std::max(b.latMax, p.y);
    }
    if (lons.empty()) return std::nullopt;
    const bool north = containsPole(grid, projection, 90.0);
    const bool south = containsPole(grid, projection, -90.0);
    if (north) b.latMax = 90.0;
    if (south) b.latMin = -90.0;
    if (north || south) {
        b.lonMin = -180.0;
        b.lonMax = 180.0;
        return b;
    }
    // The longitudes span the circle but for the widest gap between neighbours: the domain
    // is the rest, which crosses the antimeridian when the gap does not.
    std::sort(lons.begin(), lons.end());
    double widestGap = lons.front() + 360.0 - lons.back();
    b.lonMin = lons.front();
    b.lonMax = lons.back();
    for (std::size_t i = 1; i < lons.size(); ++i) {
        if (lons[i] - lons[i - 1] > widestGap) {
            widestGap = lons[i] - lons[i - 1];
            b.lonMin = lons[i];
            b.lonMax = lons[i - 1] + 360.0;
        }
    }
    return b;
}

}  // namespace ensil::geo

#include "geo/map_lines.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

#include "geo/domain_bounds.h"
#include "geo/natural_earth.h"

namespace ensil::geo {
namespace {

// Liang-Barsky: the part of segment a-b inside [lo, hi] as parameters t0 <= t1 in [0, 1].
std::optional<std::pair<double, double>> clipSegment(glm::dvec2 a, glm::dvec2 b, glm::dvec2 lo,
                                                     glm::dvec2 hi) {
    const glm::dvec2 d = b - a;
    double t0 = 0.0;
    double t1 = 1.0;
    const std::array<double, 4> p{-d.x, d.x, -d.y, d.y};
    const std::array<double, 4> q{a.x - lo.x, hi.x - a.x, a.y - lo.y, hi.y - a.y};
    for (std::size_t i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return std::nullopt;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
        if (t0 > t1) return std::nullopt;
    }
    return std::pair{t0, t1};
}

// A spacing of 1, 2, 5, 10, 15, 30 degrees that puts a handful of lines across the domain.
double graticuleStep(double extent) {
    for (const double step : {1.0, 2.0, 5.0, 10.0, 15.0, 30.0}) {
        if (extent / step <= 8.0) return step;
    }
    return 30.0;
}

std::string degrees(double value, char positive, char negative) {
    const long rounded = std::lround(std::abs(value));
    return std::to_string(rounded) + "\u00b0" +
           (rounded == 0 ? "" : std::string(1, value >= 0.0 ? positive : negative));
}

struct GraticuleLine {
    LonLatLine points;
    std::string label;
};

std::vector<GraticuleLine> graticule(const LonLatBounds& b) {
    const double step = graticuleStep(b.extent());
    // Sampled finely enough that a meridian bending across a rotated grid stays smooth.
    const double sample = step / 32.0;
    std::vector<GraticuleLine> lines;
    for (double lon = std::ceil(b.lonMin / step) * step; lon <= b.lonMax; lon += step) {
        lines.push_back({{}, degrees(std::remainder(lon, 360.0), 'E', 'W')});
        LonLatLine& line = lines.back().points;
        for (double lat = std::max(-89.9, b.latMin); lat <= std::min(89.9, b.latMax) + sample;
             lat += sample) {
            line.emplace_back(lon, std::min(lat, b.latMax));
        }
    }
    for (double lat = std::ceil(b.latMin / step) * step; lat <= b.latMax; lat += step) {
        lines.push_back({{}, degrees(lat, 'N', 'S')});
        LonLatLine& line = lines.back().points;
        for (double lon = b.lonMin; lon <= b.lonMax + sample; lon += sample) {
            line.emplace_back(std::min(lon, b.lonMax), lat);
        }
    }
    return lines;
}

void addLine(const LonLatLine& line, MapLineKind kind, const std::string& label,
             const data::Grid& grid, const MapProjection& projection, std::vector<MapLine>& out) {
    const glm::dvec2 lo{grid.x().minValue(), grid.y().minValue()};
    const glm::dvec2 hi{grid.x().maxValue(), grid.y().maxValue()};
    double longestStep = std::max(hi.x - lo.x, hi.y - lo.y);
    if (projection.xWraps()) longestStep = std::min(longestStep, 180.0);
    std::vector<glm::dvec2> points = line;
    projection.toGrid(points);
    std::vector<std::vector<glm::dvec2>> pieces;
    clipToRectangle(points, lo, hi, longestStep, pieces);
    for (auto& piece : pieces) out.push_back(MapLine{kind, std::move(piece), label});
}

}  // namespace

void clipToRectangle(const std::vector<glm::dvec2>& line, glm::dvec2 lo, glm::dvec2 hi,
                     double longestStep, std::vector<std::vector<glm::dvec2>>& out) {
    std::vector<glm::dvec2> current;
    const auto finish = [&] {
        if (current.size() > 1) out.push_back(std::move(current));
        current.clear();
    };
    for (std::size_t i = 1; i < line.size(); ++i) {
        const glm::dvec2 a = line[i - 1];
        const glm::dvec2 b = line[i];
        if (!std::isfinite(a.x) || !std::isfinite(b.x) || !std::isfinite(a.y) ||
            !std::isfinite(b.y) || glm::distance(a, b) > longestStep) {
            finish();
            continue;
        }
        const auto inside = clipSegment(a, b, lo, hi);
        if (!inside) {
            finish();
            continue;
        }
        const glm::dvec2 start = a + inside->first * (b - a);
        const glm::dvec2 end = a + inside->second * (b - a);
        if (current.empty() || inside->first > 0.0) {
            finish();
            current.push_back(start);
        }
        current.push_back(end);
        if (inside->second < 1.0) finish();
    }
    finish();
}

std::vector<MapLine> mapLinesFor(const data::Grid& grid, const MapProjection& projection) {
    std::vector<MapLine> lines;
    const std::optional<LonLatBounds> bounds = lonLatBounds(grid, projection);
    if (!bounds) return lines;
    const MapScale scale = scaleForExtent(bounds->extent());
    for (const LonLatLine& line : naturalEarthLines(MapFeature::Coastlines, scale)) {
        addLine(line, MapLineKind::Coastline, {}, grid, projection, lines);
    }
    for (const LonLatLine& line : naturalEarthLines(MapFeature::Borders, scale)) {
        addLine(line, MapLineKind::Border, {}, grid, projection, lines);
    }
    if (projection.kind() != MapProjection::Kind::LonLat) {
        for (const GraticuleLine& line : graticule(*bounds)) {
            addLine(line.points, MapLineKind::Graticule, line.label, grid, projection, lines);
        }
    }
    return lines;
}

std::vector<MapLine> mapLinesFor(const data::Grid& grid, const data::GridMapping& mapping) {
    return mapLinesFor(grid, MapProjection::forGrid(grid, mapping));
}

}  // namespace ensil::geo

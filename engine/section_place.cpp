#include "engine/section_place.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "data/ascii_case.h"
#include "data/display_frame.h"
#include "data/error.h"
#include "geo/map_lines.h"
#include "geo/map_projection.h"
#include "gl/axis_ticks.h"
#include "gl/view_overlay.h"

namespace ensil::engine {
namespace {

using data::Error;
using data::ErrorKind;

std::string tickText(double value) { return gl::formatTick(value).toStdString(); }

// A place in a message: to a hundredth of a degree (or unit).
double rounded(double value) { return std::round(value * 100.0) / 100.0; }

// The whole text as a number, with what follows it in `rest` (spaces trimmed).
std::optional<double> leadingNumber(const std::string& text, std::string& rest) {
    const char* begin = text.c_str();
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin || !std::isfinite(value)) return std::nullopt;
    rest = std::string(end);
    rest.erase(0, rest.find_first_not_of(' '));
    rest.erase(rest.find_last_not_of(' ') + 1);
    return value;
}

std::string trimmed(std::string text) {
    text.erase(0, text.find_first_not_of(" \t"));
    text.erase(text.find_last_not_of(" \t") + 1);
    return text;
}

// An angle with an optional hemisphere letter: "45", "45N", "45 s"; nullopt when it does not
// read or lies outside +-limit.
std::optional<double> parseAngle(const std::string& text, char positive, char negative,
                                 double limit) {
    std::string rest;
    auto value = leadingNumber(trimmed(text), rest);
    if (!value) return std::nullopt;
    if (rest.starts_with("°")) rest.erase(0, std::string("°").size());  // as degreesText writes
    if (rest.size() == 1 && std::toupper(static_cast<unsigned char>(rest[0])) == positive) {
        rest.clear();
    } else if (rest.size() == 1 && std::toupper(static_cast<unsigned char>(rest[0])) == negative) {
        rest.clear();
        *value = -*value;
    }
    if (!rest.empty() || std::abs(*value) > limit) return std::nullopt;
    return value;
}

// Great-circle distance in km between two longitude/latitude points (the haversine formula).
double kilometresBetween(glm::dvec2 a, glm::dvec2 b) {
    constexpr double kEarthRadiusKm = 6371.0;
    constexpr double kRadians = std::numbers::pi / 180.0;
    const double dLat = (b.y - a.y) * kRadians, dLon = (b.x - a.x) * kRadians;
    const double h = std::sin(dLat / 2) * std::sin(dLat / 2) +
                     std::cos(a.y * kRadians) * std::cos(b.y * kRadians) * std::sin(dLon / 2) *
                         std::sin(dLon / 2);
    return 2.0 * kEarthRadiusKm * std::asin(std::min(1.0, std::sqrt(h)));
}

// n points along the great circle from a to b (longitude, latitude in degrees).
std::vector<glm::dvec2> greatCircle(glm::dvec2 a, glm::dvec2 b, std::size_t n) {
    constexpr double kRadians = std::numbers::pi / 180.0;
    const auto unit = [](glm::dvec2 p) {
        const double lon = p.x * kRadians, lat = p.y * kRadians;
        return glm::dvec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                          std::sin(lat));
    };
    const glm::dvec3 ua = unit(a), ub = unit(b);
    const double omega = std::acos(std::clamp(glm::dot(ua, ub), -1.0, 1.0));
    std::vector<glm::dvec2> points;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / static_cast<double>(n - 1);
        glm::dvec3 p = omega < 1e-12 ? ua
                                     : (std::sin((1 - t) * omega) * ua + std::sin(t * omega) * ub) /
                                           std::sin(omega);
        points.emplace_back(std::atan2(p.y, p.x) / kRadians,
                            std::asin(std::clamp(p.z, -1.0, 1.0)) / kRadians);
    }
    // Longitudes continue across the date line rather than jump by 360.
    for (std::size_t i = 1; i < points.size(); ++i) {
        while (points[i].x - points[i - 1].x > 180.0) points[i].x -= 360.0;
        while (points[i].x - points[i - 1].x < -180.0) points[i].x += 360.0;
    }
    return points;
}

// Whether the grid's longitudes go round the globe (0 to 357 by 3): then a place between the
// last and the first lies in the cell across the seam.
bool goesRoundTheGlobe(const data::Grid& grid, const geo::MapProjection& projection) {
    const data::Axis& x = grid.x();
    const double step = (x.maxValue() - x.minValue()) / static_cast<double>(x.size() - 1);
    return projection.kind() == geo::MapProjection::Kind::LonLat && x.isUniform() &&
           std::abs(x.maxValue() - x.minValue() + step - 360.0) < 0.5 * step;
}

// Grid axis coordinates to fractional grid indices; NaN outside. Round the globe, an x past
// the last column (or before the first) is in the seam's cell, index nx - 1 to nx.
glm::dvec2 indexOf(const data::Grid& grid, glm::dvec2 p, bool roundTheGlobe = false) {
    double i = grid.x().indexOf(p.x);
    if (roundTheGlobe && !std::isfinite(i) && std::isfinite(p.x)) {
        const data::Axis& x = grid.x();
        const double step = (x.maxValue() - x.minValue()) / static_cast<double>(x.size() - 1);
        // Past the axis's maximum, measured from it (wrapped by 360 into [0, 360)).
        const double past = std::fmod(std::fmod(p.x - x.maxValue(), 360.0) + 360.0, 360.0);
        if (past < step) {
            const bool increasing = x.back() > x.front();
            // An increasing axis goes on from its last column into the seam; a decreasing one
            // from its first, which is index 0 (the seam then lies between columns 0 and -1:
            // not taken here, as longitude axes in files increase).
            if (increasing) i = static_cast<double>(x.size() - 1) + past / step;
        }
    }
    return {i, grid.y().indexOf(p.y)};
}

bool inside(glm::dvec2 index) { return std::isfinite(index.x) && std::isfinite(index.y); }

// Ticks for degrees as maps label them: every 1, 2, 5, 10, 15, 30, 45, 60 or 90 degrees, the
// finest step that gives at most 8 of them.
std::vector<double> degreeTicks(double lo, double hi) {
    if (lo > hi) std::swap(lo, hi);
    std::vector<double> ticks;
    for (const double step : {1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 45.0, 60.0, 90.0}) {
        if ((hi - lo) / step > 8.0 && step < 90.0) continue;
        for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9; t += step) {
            ticks.push_back(t);
        }
        break;
    }
    return ticks;
}

// Ticks of `values` (one per column, monotonic; round numbers, or `degrees`) placed at the
// columns' positions.
std::vector<SectionTick> ticksAlong(const std::vector<double>& values,
                                    const std::vector<double>& positions, bool degrees,
                                    const std::function<std::string(double)>& text) {
    std::vector<SectionTick> ticks;
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    for (const double t : degrees ? degreeTicks(*lo, *hi) : gl::niceTicks(*lo, *hi, 6)) {
        for (std::size_t i = 0; i + 1 < values.size(); ++i) {
            const double a = values[i], b = values[i + 1];
            if ((t - a) * (t - b) > 0.0 || a == b) continue;
            const double f = (t - a) / (b - a);
            ticks.push_back({positions[i] + f * (positions[i + 1] - positions[i]), text(t)});
            break;
        }
    }
    return ticks;
}

std::string axisTitle(const data::Axis& axis, const std::string& units) {
    return units.empty() ? axis.name : axis.name + " (" + units + ")";
}

// A horizontal axis's ticks across the map: degrees for longitude and latitude axes, else the
// axis's own round numbers.
SectionAxis mapAxis(const data::Grid& grid, const data::DisplayFrame& frame, int a, bool degrees) {
    const data::Axis& axis = grid.axis(a);
    SectionAxis out;
    const gl::AxisLabelling labelling = gl::labellingFor(axis);
    out.title = degrees ? (a == 0 ? "longitude" : "latitude") : axisTitle(axis, labelling.units);
    const double extent = frame.boxMax()[a];
    for (const double t :
         degrees ? degreeTicks(axis.minValue(), axis.maxValue()) : labelling.ticks) {
        glm::dvec3 p{grid.x().front(), grid.y().front(), grid.z().front()};
        p[a] = t;
        out.ticks.push_back(
            {frame.toDisplay(p)[a] / extent,
             degrees ? degreesText(t, a == 1) : tickText(t * labelling.shownPerUnit)});
    }
    std::sort(out.ticks.begin(), out.ticks.end(),
              [](const SectionTick& x, const SectionTick& y) { return x.position < y.position; });
    return out;
}

// The vertical axis of a cross-section: its round levels (standard pressures) at their heights.
SectionAxis verticalAxis(const data::Grid& grid, const data::DisplayFrame& frame) {
    SectionAxis out;
    const gl::AxisLabelling labelling = gl::labellingFor(grid.z());
    out.title = axisTitle(grid.z(), labelling.units);
    for (const double t : labelling.ticks) {
        const glm::dvec3 p{grid.x().front(), grid.y().front(), t};
        out.ticks.push_back(
            {frame.toDisplay(p).z / frame.boxMax().z, tickText(t * labelling.shownPerUnit)});
    }
    return out;
}

// The vertical index of a map's level, or an error naming the axis's range.
double levelIndex(const data::Grid& grid, const SectionPlace& place, std::string& text) {
    const data::Axis& z = grid.z();
    const std::string units = data::asciiLower(place.levelUnits);
    const auto range = [&] {
        return z.name + " runs from " + tickText(z.front()) + " to " + tickText(z.back()) +
               (z.units.empty() ? "" : " " + z.units);
    };
    if (units == "index") {
        text = "level " + tickText(place.level) + " (" + z.name + " " +
               tickText(z.valueAt(place.level)) + (z.units.empty() ? "" : " " + z.units) + ")";
        if (place.level < 0 || place.level > static_cast<double>(z.size() - 1)) {
            throw Error(ErrorKind::InvalidArgument,
                        "level index " + tickText(place.level) + " is not one of the grid's " +
                            std::to_string(z.size()) + " levels (0 to " +
                            std::to_string(z.size() - 1) + ")");
        }
        return place.level;
    }
    double coordinate = place.level;
    text =
        tickText(place.level) + (place.levelUnits.empty() ? (z.units.empty() ? "" : " " + z.units)
                                                          : " " + place.levelUnits);
    if (!units.empty()) {
        const double perUnit = data::hectopascalsPer(place.levelUnits);
        const double perMetre = data::metresPer(place.levelUnits);
        const double axisPressure = data::hectopascalsPer(z.units);
        const double axisLength = data::metresPer(z.units);
        if (perUnit > 0 && axisPressure > 0) {
            coordinate = place.level * perUnit / axisPressure;
        } else if (perMetre > 0 && axisLength > 0) {
            coordinate = place.level * perMetre / axisLength;
        } else {
            throw Error(ErrorKind::InvalidArgument,
                        "a level of " + text + " cannot be placed on the vertical axis " + z.name +
                            (z.units.empty() ? " (no units)" : " (in " + z.units + ")") +
                            ": give it in the axis's units, or as index:N");
        }
    }
    const double index = z.indexOf(coordinate);
    if (!std::isfinite(index)) {
        throw Error(ErrorKind::InvalidArgument,
                    "a level of " + text + " lies outside the data: " + range());
    }
    return index;
}

// The grid's horizontal border as longitude/latitude points (for the longitudes or latitudes a
// cross-section along a parallel or a meridian may take).
std::vector<glm::dvec2> borderLonLat(const data::Grid& grid, const geo::MapProjection& projection) {
    std::vector<glm::dvec2> points;
    constexpr int kPerSide = 64;
    for (int i = 0; i <= kPerSide; ++i) {
        const double t = static_cast<double>(i) / kPerSide;
        const double x = grid.x().valueAt(t * static_cast<double>(grid.nx() - 1));
        const double y = grid.y().valueAt(t * static_cast<double>(grid.ny() - 1));
        points.insert(points.end(), {{x, grid.y().front()},
                                     {x, grid.y().back()},
                                     {grid.x().front(), y},
                                     {grid.x().back(), y}});
    }
    projection.toLonLat(points);
    std::erase_if(points, [](glm::dvec2 p) { return !std::isfinite(p.x) || !std::isfinite(p.y); });
    return points;
}

// The longest run of consecutive points (longitude, latitude) inside the grid, as fractional
// grid indices, with the points themselves in `kept`.
std::vector<glm::dvec2> longestInside(const data::Grid& grid, const geo::MapProjection& projection,
                                      const std::vector<glm::dvec2>& lonLat,
                                      std::vector<glm::dvec2>& kept) {
    std::vector<glm::dvec2> xy = lonLat;
    projection.toGrid(xy);
    const bool round = goesRoundTheGlobe(grid, projection);
    std::vector<glm::dvec2> best, bestLonLat, run, runLonLat;
    for (std::size_t i = 0; i <= xy.size(); ++i) {
        const glm::dvec2 index = i < xy.size() ? indexOf(grid, xy[i], round) : glm::dvec2(NAN);
        if (inside(index)) {
            run.push_back(index);
            runLonLat.push_back(lonLat[i]);
            continue;
        }
        if (run.size() > best.size()) {
            best = run;
            bestLonLat = runLonLat;
        }
        run.clear();
        runLonLat.clear();
    }
    kept = bestLonLat;
    return best;
}

// Positions 0 to 1 by the distance travelled along the points.
std::vector<double> positionsAlong(const std::vector<glm::dvec2>& points, bool geographic,
                                   double& total) {
    std::vector<double> positions{0.0};
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double step = geographic ? kilometresBetween(points[i - 1], points[i])
                                       : glm::distance(points[i - 1], points[i]);
        positions.push_back(positions.back() + step);
    }
    total = positions.back();
    if (total > 0) {
        for (double& p : positions) p /= total;
    }
    return positions;
}

void placeMap(const data::Ensemble& ensemble, const SectionPlace& place,
              const geo::MapProjection& projection, PlacedSection& out) {
    const data::Grid& grid = ensemble.grid;
    const data::DisplayFrame frame(grid, 1.0F, place.verticalAxis);
    const double zIndex = levelIndex(grid, place, out.placeText);
    out.lattice = prep::horizontalLattice(grid, zIndex);
    out.levelHeight =
        frame.toDisplay({grid.x().front(), grid.y().front(), grid.z().valueAt(zIndex)}).z /
        frame.boxMax().z;
    const glm::vec3 box = frame.boxMax();
    for (std::size_t i = 0; i < grid.nx(); ++i) {
        out.columnPositions.push_back(
            frame.toDisplay({grid.x().values[i], grid.y().front(), grid.z().front()}).x / box.x);
    }
    for (std::size_t j = 0; j < grid.ny(); ++j) {
        out.rowPositions.push_back(
            frame.toDisplay({grid.x().front(), grid.y().values[j], grid.z().front()}).y / box.y);
    }
    out.aspect = static_cast<double>(box.x / box.y);
    const bool degrees = projection.kind() == geo::MapProjection::Kind::LonLat;
    out.bottom = mapAxis(grid, frame, 0, degrees);
    out.left = mapAxis(grid, frame, 1, degrees);
    for (const geo::MapLine& line : geo::mapLinesFor(grid, ensemble.gridMapping)) {
        SectionLine placed;
        for (const glm::dvec2& p : line.points) {
            const glm::vec3 d = frame.toDisplay({p.x, p.y, grid.z().front()});
            placed.points.emplace_back(d.x / box.x, d.y / box.y);
        }
        if (line.kind == geo::MapLineKind::Graticule && !line.label.empty() &&
            !placed.points.empty()) {
            out.graticuleLabels.push_back({placed.points.front(), line.label});
        }
        (line.kind == geo::MapLineKind::Graticule ? out.graticule : out.mapLines)
            .push_back(std::move(placed));
    }
}

void placeCrossSection(const data::Ensemble& ensemble, const SectionPlace& place,
                       const geo::MapProjection& projection, PlacedSection& out) {
    const data::Grid& grid = ensemble.grid;
    const bool geographic = projection.hasGeography();
    const std::size_t samples = std::max<std::size_t>(64, 2 * std::max(grid.nx(), grid.ny()));
    std::vector<glm::dvec2> path, lonLat;
    if (place.kind == SectionKind::Path) {
        out.placeText =
            geographic
                ? degreesText(place.from.x, false) + " " + degreesText(place.from.y, true) +
                      " to " + degreesText(place.to.x, false) + " " + degreesText(place.to.y, true)
                : tickText(place.from.x) + "," + tickText(place.from.y) + " to " +
                      tickText(place.to.x) + "," + tickText(place.to.y);
        std::vector<glm::dvec2> points;
        if (geographic) {
            points = greatCircle(place.from, place.to, samples);
        } else {
            for (std::size_t i = 0; i < samples; ++i) {
                const double t = static_cast<double>(i) / static_cast<double>(samples - 1);
                points.push_back(place.from + t * (place.to - place.from));
            }
        }
        std::vector<glm::dvec2> xy = points;
        if (geographic) projection.toGrid(xy);
        for (std::size_t i = 0; i < xy.size(); ++i) {
            const glm::dvec2 index = indexOf(grid, xy[i], goesRoundTheGlobe(grid, projection));
            if (!inside(index)) {
                throw Error(ErrorKind::InvalidArgument,
                            "the path from " + out.placeText + " leaves the data near " +
                                (geographic ? degreesText(rounded(points[i].x), false) + " " +
                                                  degreesText(rounded(points[i].y), true)
                                            : tickText(rounded(points[i].x)) + "," +
                                                  tickText(rounded(points[i].y))));
            }
            path.push_back(index);
        }
        lonLat = points;
    } else {
        const bool alongParallel = place.kind == SectionKind::Latitude;
        const double fixed = alongParallel ? place.latitude : place.longitude;
        out.placeText = degreesText(fixed, alongParallel);
        if (!geographic) {
            throw Error(ErrorKind::InvalidArgument,
                        "a cross-section along " + out.placeText +
                            " needs data placed on the Earth, and these have no map (" +
                            projection.reason() + "): give a path in the grid's own x,y instead");
        }
        std::vector<glm::dvec2> points;
        if (projection.kind() == geo::MapProjection::Kind::LonLat) {
            // Through the grid's own columns (or rows): the section holds the data's values.
            const data::Axis& across = alongParallel ? grid.x() : grid.y();
            for (const double v : across.values) {
                points.push_back(alongParallel ? glm::dvec2(v, fixed) : glm::dvec2(fixed, v));
            }
        } else {
            const std::vector<glm::dvec2> border = borderLonLat(grid, projection);
            double lo = 1e300, hi = -1e300;
            for (const glm::dvec2& p : border) {
                lo = std::min(lo, alongParallel ? p.x : p.y);
                hi = std::max(hi, alongParallel ? p.x : p.y);
            }
            for (std::size_t i = 0; i < samples && lo < hi; ++i) {
                const double v =
                    lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(samples - 1);
                points.push_back(alongParallel ? glm::dvec2(v, fixed) : glm::dvec2(fixed, v));
            }
        }
        path = longestInside(grid, projection, points, lonLat);
        if (path.size() < 2) {
            // The data's extent in true degrees, whatever its grid's own coordinates.
            double west = 1e300, east = -1e300, south = 1e300, north = -1e300;
            for (const glm::dvec2& p : borderLonLat(grid, projection)) {
                west = std::min(west, p.x);
                east = std::max(east, p.x);
                south = std::min(south, p.y);
                north = std::max(north, p.y);
            }
            throw Error(ErrorKind::InvalidArgument,
                        out.placeText + " does not cross the data, which lie from " +
                            degreesText(rounded(south), true) + " to " +
                            degreesText(rounded(north), true) + " and from " +
                            degreesText(rounded(west), false) + " to " +
                            degreesText(rounded(east), false));
        }
    }
    out.lattice = prep::verticalLattice(grid, path, goesRoundTheGlobe(grid, projection));
    double total = 0.0;
    out.columnPositions = positionsAlong(lonLat, geographic, total);
    const data::DisplayFrame frame(grid, 1.0F, place.verticalAxis);
    // Across the seam of a global grid the x index runs past the last column: one more step.
    const auto xAt = [&grid](double i) {
        const auto last = static_cast<double>(grid.nx() - 1);
        if (i <= last) return grid.x().valueAt(i);
        return grid.x().values.back() +
               (i - last) * (grid.x().values.back() - grid.x().values[grid.nx() - 2]);
    };
    for (const glm::dvec2& index : path) {
        const glm::vec3 d =
            frame.toDisplay({xAt(index.x), grid.y().valueAt(index.y), grid.z().front()});
        out.pathOnMap.emplace_back(d.x / frame.boxMax().x, d.y / frame.boxMax().y);
    }
    for (std::size_t k = 0; k < grid.nz(); ++k) {
        out.rowPositions.push_back(
            frame.toDisplay({grid.x().front(), grid.y().front(), grid.z().values[k]}).z /
            frame.boxMax().z);
    }
    out.aspect = 2.0;  // a cross-section is read along: wider than high
    out.left = verticalAxis(grid, frame);
    if (place.kind == SectionKind::Path) {
        std::vector<double> along;
        for (const double p : out.columnPositions) along.push_back(p * total);
        out.bottom.title = geographic ? "distance along the path (km)" : "distance along the path";
        out.bottom.ticks = ticksAlong(along, out.columnPositions, false, tickText);
    } else {
        const bool alongParallel = place.kind == SectionKind::Latitude;
        std::vector<double> values;
        values.reserve(lonLat.size());
        for (const glm::dvec2& p : lonLat) values.push_back(alongParallel ? p.x : p.y);
        out.bottom.title = alongParallel ? "longitude" : "latitude";
        out.bottom.ticks = ticksAlong(values, out.columnPositions, true, [alongParallel](double v) {
            return degreesText(v, !alongParallel);
        });
    }
}

}  // namespace

std::string degreesText(double value, bool latitude) {
    if (!latitude) value = std::remainder(value, 360.0);  // within -180 to 180
    const double magnitude = std::abs(value);
    if (magnitude < 1e-9 || (!latitude && std::abs(magnitude - 180.0) < 1e-9)) {
        return tickText(magnitude) + "°";
    }
    const char* hemisphere = latitude ? (value > 0 ? "N" : "S") : (value > 0 ? "E" : "W");
    return tickText(magnitude) + "°" + hemisphere;
}

PlacedSection placeSection(const data::Ensemble& ensemble, const SectionPlace& place) {
    const geo::MapProjection projection =
        geo::MapProjection::forGrid(ensemble.grid, ensemble.gridMapping);
    PlacedSection out;
    if (place.kind == SectionKind::Map) {
        placeMap(ensemble, place, projection, out);
    } else {
        placeCrossSection(ensemble, place, projection, out);
    }
    return out;
}

std::optional<SectionPlace> parseSectionPlace(SectionKind kind, const std::string& text,
                                              std::string& problem) {
    switch (kind) {
        case SectionKind::Map:
            return parseLevel(text, problem);
        case SectionKind::Latitude:
            return parseLatitude(text, problem);
        case SectionKind::Longitude:
            return parseLongitude(text, problem);
        case SectionKind::Path:
            break;
    }
    return parsePath(text, problem);
}

std::optional<SectionPlace> parseLevel(const std::string& text, std::string& problem) {
    SectionPlace place;
    place.kind = SectionKind::Map;
    const std::string t = trimmed(text);
    std::string rest;
    if (data::asciiLower(t).starts_with("index:")) {
        const auto value = leadingNumber(t.substr(6), rest);
        if (value && rest.empty() && *value >= 0 && std::floor(*value) == *value) {
            place.level = *value;
            place.levelUnits = "index";
            return place;
        }
    } else if (const auto value = leadingNumber(t, rest)) {
        if (rest.empty() || data::hectopascalsPer(rest) > 0 || data::metresPer(rest) > 0) {
            place.level = *value;
            place.levelUnits = rest;
            return place;
        }
    }
    problem = "'" + text +
              "' is not a level: give a number with its units (500hPa, 85000Pa, 5km, 1500m), "
              "a number in the vertical axis's own units, or index:N (a level from 0)";
    return std::nullopt;
}

std::optional<SectionPlace> parseLatitude(const std::string& text, std::string& problem) {
    const auto value = parseAngle(text, 'N', 'S', 90.0);
    if (!value) {
        problem = "'" + text + "' is not a latitude: give degrees north, -90 to 90 (45, 45N, 30S)";
        return std::nullopt;
    }
    SectionPlace place;
    place.kind = SectionKind::Latitude;
    place.latitude = *value;
    return place;
}

std::optional<SectionPlace> parseLongitude(const std::string& text, std::string& problem) {
    const auto value = parseAngle(text, 'E', 'W', 360.0);
    if (!value) {
        problem =
            "'" + text + "' is not a longitude: give degrees east, -360 to 360 (10, 10E, 75W)";
        return std::nullopt;
    }
    SectionPlace place;
    place.kind = SectionKind::Longitude;
    place.longitude = *value;
    return place;
}

std::optional<SectionPlace> parsePath(const std::string& text, std::string& problem) {
    const auto colon = text.find(':');
    const auto point = [](const std::string& part) -> std::optional<glm::dvec2> {
        const auto comma = part.find(',');
        if (comma == std::string::npos) return std::nullopt;
        std::string rest;
        const auto x = leadingNumber(trimmed(part.substr(0, comma)), rest);
        if (!x || !rest.empty()) return std::nullopt;
        const auto y = leadingNumber(trimmed(part.substr(comma + 1)), rest);
        if (!y || !rest.empty()) return std::nullopt;
        return glm::dvec2(*x, *y);
    };
    const auto from = colon == std::string::npos ? std::nullopt : point(text.substr(0, colon));
    const auto to = colon == std::string::npos ? std::nullopt : point(text.substr(colon + 1));
    if (!from || !to || *from == *to) {
        problem = "'" + text +
                  "' is not a path: give two different points as LON,LAT:LON,LAT in degrees "
                  "(-10,50:20,40), or the grid's own X,Y:X,Y for data without a map";
        return std::nullopt;
    }
    SectionPlace place;
    place.kind = SectionKind::Path;
    place.from = *from;
    place.to = *to;
    return place;
}

}  // namespace ensil::engine

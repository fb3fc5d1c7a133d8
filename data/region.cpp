#include "data/region.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>

#include "data/ascii_case.h"
#include "data/number_text.h"

namespace ensil::data {
namespace {

constexpr const char* kForm =
    "give it as LON0,LON1,LAT0,LAT1 in degrees, e.g. -10,40,35,72 (LON0 > LON1 crosses the date "
    "line or the 0/360 seam: 350,20,35,70)";
// Points this close to an edge (about 10 m) lie on it: coordinates are often stored as float,
// which near 360 degrees resolves only 3e-5.
constexpr double kEdgeSlack = 1e-4;

[[noreturn]] void refuse(const std::string& text, const std::string& why) {
    throw Error(ErrorKind::InvalidArgument,
                "the region '" + text + "' " + why + ": " + std::string(kForm));
}

// The whole of `text` (spaces around allowed) as a finite number.
std::optional<double> number(const std::string& text) {
    const std::string t = asciiTrimmed(text);
    double value = 0.0;
    const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (t.empty() || error != std::errc() || end != t.data() + t.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

// The shortest text that reads back as the same double ("-10", "0.25").
std::string shortest(double value) {
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : std::to_string(value);
}

// Degrees east from LON0 to LON1, eastwards: across the date line when LON1 < LON0.
double widthOf(const Region& r) {
    return r.lon1 > r.lon0 ? r.lon1 - r.lon0 : r.lon1 + 360.0 - r.lon0;
}

void check(const Region& r, const std::string& text) {
    const std::array<std::pair<const char*, double>, 2> lons{{{"LON0", r.lon0}, {"LON1", r.lon1}}};
    for (const auto& [name, lon] : lons) {
        if (!(lon >= -360.0 && lon <= 360.0)) {
            refuse(text, "has " + std::string(name) + " = " + shortest(lon) +
                             ", not a longitude from -360 to 360");
        }
    }
    const std::array<std::pair<const char*, double>, 2> lats{{{"LAT0", r.lat0}, {"LAT1", r.lat1}}};
    for (const auto& [name, lat] : lats) {
        if (!(lat >= -90.0 && lat <= 90.0)) {
            refuse(text, "has " + std::string(name) + " = " + shortest(lat) +
                             ", not a latitude from -90 to 90");
        }
    }
    if (r.lon0 == r.lon1) refuse(text, "has no width (LON0 = LON1)");
    if (r.lat0 == r.lat1) refuse(text, "has no height (LAT0 = LAT1)");
    const double width = widthOf(r);
    if (width <= 0.0 || width > 360.0) {
        refuse(text, "spans " + shortest(r.lon1 - r.lon0) +
                         " degrees of longitude; a box spans more than 0 and at most 360");
    }
}

std::string extentOf(const Axis& axis) {
    return readableNumber(axis.front(), 9) + " to " + readableNumber(axis.back(), 9);
}

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

Region parseRegion(const std::string& text) {
    std::array<double, 4> values{};
    std::size_t count = 0;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = text.find(',', start);
        const std::string part =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (count < values.size()) {
            const std::optional<double> value = number(part);
            if (!value) {
                constexpr std::array<const char*, 4> kNames{"LON0", "LON1", "LAT0", "LAT1"};
                refuse(text, asciiTrimmed(part).empty()
                                 ? "has no " + std::string(kNames.at(count))
                                 : "has '" + asciiTrimmed(part) + "' for " + kNames.at(count) +
                                       ", which is not a number");
            }
            values.at(count) = *value;
        }
        ++count;
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (count != values.size()) refuse(text, "has " + plural(count, "value", "values"));
    const Region region{values[0], values[1], values[2], values[3]};
    check(region, text);
    return region;
}

void checkRegion(const Region& region) { check(region, regionText(region)); }

std::string regionText(const Region& region) {
    return shortest(region.lon0) + "," + shortest(region.lon1) + "," + shortest(region.lat0) + "," +
           shortest(region.lat1);
}

std::size_t HorizontalWindow::columnCount() const {
    std::size_t n = 0;
    for (const ColumnRun& run : columns) n += run.count;
    return n;
}

HorizontalWindow regionWithin(const Grid& grid, const GridMapping& mapping, const Region& region,
                              const std::string& source) {
    checkRegion(region);
    const Axis& x = grid.x();
    const Axis& y = grid.y();
    const std::string asked = "cannot keep the region " + regionText(region) + " of " + source;
    const std::string only =
        "; a region in degrees is cut only from a regular longitude-latitude grid (1D "
        "longitude and latitude axes)";
    if (!mapping.empty() && mapping.name != "latitude_longitude") {
        throw Error(ErrorKind::InvalidArgument,
                    asked + ": it lies on a '" + mapping.name + "' grid, whose axes '" + x.name +
                        "' and '" + y.name + "' are not true longitudes and latitudes" + only);
    }
    if (!isLongitudeAxis(x) || !isLatitudeAxis(y)) {
        const auto axisText = [](const Axis& a) {
            return "'" + a.name + "'" + (a.units.empty() ? "" : " in " + a.units);
        };
        throw Error(ErrorKind::InvalidArgument, asked + ": its horizontal axes (" + axisText(x) +
                                                    ", " + axisText(y) +
                                                    ") are not longitude and latitude" + only);
    }

    // Each column's longitude moved by whole turns to LON0 or east of it, kept when it lies
    // no further east than LON1.
    struct Column {
        double lon;
        std::size_t index;
        double shift;
    };
    const double west = region.lon0;
    const double east = west + widthOf(region);
    std::vector<Column> kept;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double turns = std::floor((x.values[i] - west + kEdgeSlack) / 360.0);
        const double shift = -360.0 * turns;
        if (x.values[i] + shift <= east + kEdgeSlack)
            kept.push_back({x.values[i] + shift, i, shift});
    }
    // In the direction the file's longitudes run, so that each run of columns reads forwards.
    const bool increasing = x.back() > x.front();
    std::sort(kept.begin(), kept.end(), [increasing](const Column& a, const Column& b) {
        return increasing ? a.lon < b.lon : a.lon > b.lon;
    });
    HorizontalWindow window;
    std::optional<double> last;
    for (const Column& c : kept) {
        // A grid that holds both 0 and 360 (or -180 and 180) has that meridian once.
        if (last && std::abs(c.lon - *last) <= kEdgeSlack) continue;
        last = c.lon;
        if (!window.columns.empty()) {
            ColumnRun& run = window.columns.back();
            if (run.first + run.count == c.index && run.shift == c.shift) {
                ++run.count;
                continue;
            }
        }
        window.columns.push_back({c.index, 1, c.shift});
    }
    // Past 360 the longitudes are written a turn lower (350,20 keeps -10 .. 20, as -10,20 does),
    // so that the same box gives the same grid however it is typed and no axis reads 380.
    const double eastmost = kept.empty() ? 0.0 : increasing ? kept.back().lon : kept.front().lon;
    if (eastmost > 360.0 + kEdgeSlack) {
        for (ColumnRun& run : window.columns) run.shift -= 360.0;
    }

    const double south = std::min(region.lat0, region.lat1) - kEdgeSlack;
    const double north = std::max(region.lat0, region.lat1) + kEdgeSlack;
    for (std::size_t j = 0; j < y.size(); ++j) {
        if (y.values[j] < south || y.values[j] > north) continue;
        if (window.rowCount == 0) window.firstRow = j;
        ++window.rowCount;  // the axis is monotonic, so the rows within are contiguous
    }

    const std::size_t columns = window.columnCount();
    if (columns < 2 || window.rowCount < 2) {
        const std::string holds = columns == 0 || window.rowCount == 0
                                      ? "holds no grid point"
                                      : "holds only " + plural(columns, "column", "columns") +
                                            " and " + plural(window.rowCount, "row", "rows") +
                                            " (a volume needs 2 of each)";
        throw RegionOutsideGrid("the region " + regionText(region) + " " + holds + " of " + source +
                                ", whose grid spans longitudes " + extentOf(x) + " and latitudes " +
                                extentOf(y) + " (" + std::to_string(x.size()) + " x " +
                                std::to_string(y.size()) + " points)");
    }
    return window;
}

Grid gridWindow(const Grid& grid, const HorizontalWindow& window) {
    const std::size_t nx = grid.nx();
    const std::size_t ny = grid.ny();
    const auto refuseWindow = [&](const std::string& why) {
        throw Error(ErrorKind::InvalidArgument, "cannot cut the grid of " + std::to_string(nx) +
                                                    " x " + std::to_string(ny) +
                                                    " points to a window that " + why);
    };
    if (window.columnCount() < 2 || window.rowCount < 2) {
        refuseWindow("holds fewer than 2 columns or rows");
    }
    if (window.firstRow >= ny || window.rowCount > ny - window.firstRow) {
        refuseWindow("leaves its rows");
    }
    Axis x = grid.x();
    x.values.clear();
    for (const ColumnRun& run : window.columns) {
        if (run.first >= nx || run.count > nx - run.first) refuseWindow("leaves its columns");
        for (std::size_t i = run.first; i < run.first + run.count; ++i) {
            x.values.push_back(grid.x().values[i] + run.shift);
        }
    }
    Axis y = grid.y();
    const auto firstRow = y.values.begin() + static_cast<std::ptrdiff_t>(window.firstRow);
    y.values.assign(firstRow, firstRow + static_cast<std::ptrdiff_t>(window.rowCount));
    return {std::move(x), std::move(y), grid.z()};  // refuses longitudes that jump back
}

}  // namespace ensil::data

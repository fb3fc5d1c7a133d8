#include "data/wrf_conventions.h"

#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "data/error.h"
#include "data/proj_definition.h"

namespace ensil::data {
namespace {

std::optional<double> global(const NetcdfFile& file, const char* name) {
    const std::vector<double> values = file.numericAttribute(NC_GLOBAL, name);
    if (values.empty() || !std::isfinite(values.front())) return std::nullopt;
    return values.front();
}

std::string numberText(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

}  // namespace

std::vector<std::string> wrfTimeLabels(const NetcdfFile& file, const NcDimension& dim) {
    const NcVariable* times = file.findVariable("Times");
    if (times == nullptr || times->type != NC_CHAR || times->dimIds.size() != 2 ||
        times->dimIds.front() != dim.id) {
        return {};
    }
    std::vector<std::string> labels;
    try {
        labels = file.readStrings(*times);
    } catch (const Error&) {
        return {};
    }
    for (std::string& label : labels) {
        // "YYYY-MM-DD_hh:mm:ss": the date and time joined by T, whole minutes without seconds.
        if (label.size() == 19 && label[10] == '_') {
            label[10] = 'T';
            if (label.ends_with(":00")) label.resize(16);
        }
    }
    return labels;
}

bool isWrfHorizontalDimension(const std::string& name) {
    return name == "west_east" || name == "west_east_stag" || name == "south_north" ||
           name == "south_north_stag";
}

std::optional<WrfProjection> readWrfProjection(const NetcdfFile& file) {
    const auto mapProj = global(file, "MAP_PROJ");
    if (!mapProj) return std::nullopt;
    const int code = static_cast<int>(std::lround(*mapProj));
    WrfProjection wrf;
    const auto unusable = [&](const std::string& name) {
        wrf.mapping.name = name;
        wrf.mapping.parameters = {{"wrf_map_proj", {*mapProj}}};
        wrf.usable = false;
        return wrf;
    };
    const auto truelat1 = global(file, "TRUELAT1");
    const auto truelat2 = global(file, "TRUELAT2");
    const auto standLon = global(file, "STAND_LON");
    const auto cenLat = global(file, "CEN_LAT");
    const auto cenLon = global(file, "CEN_LON");
    const auto dx = global(file, "DX");
    const auto dy = global(file, "DY");
    const std::string name = "WRF MAP_PROJ = " + numberText(*mapProj);
    // Without the centre and the spacing the grid cannot be placed, whatever the projection.
    if (!cenLat || !cenLon || !dx || !dy || *dx <= 0.0 || *dy <= 0.0) {
        return unusable(name + " without CEN_LAT, CEN_LON, DX and DY");
    }
    wrf.dx = *dx;
    wrf.dy = *dy;
    wrf.centreLongitude = *cenLon;
    wrf.centreLatitude = *cenLat;
    auto& p = wrf.mapping.parameters;
    switch (code) {
        case 1:  // Lambert conformal conic
            if (!truelat1 || !standLon) return unusable(name + " without TRUELAT1 and STAND_LON");
            wrf.mapping.name = "lambert_conformal_conic";
            p.push_back({"standard_parallel", {*truelat1, truelat2.value_or(*truelat1)}});
            p.push_back({"longitude_of_central_meridian", {*standLon}});
            p.push_back({"latitude_of_projection_origin", {*truelat1}});
            break;
        case 2:  // polar stereographic, true at TRUELAT1, on the pole of TRUELAT1's hemisphere
            if (!truelat1 || !standLon) return unusable(name + " without TRUELAT1 and STAND_LON");
            wrf.mapping.name = "polar_stereographic";
            p.push_back({"latitude_of_projection_origin", {*truelat1 < 0.0 ? -90.0 : 90.0}});
            p.push_back({"straight_vertical_longitude_from_pole", {*standLon}});
            p.push_back({"standard_parallel", {*truelat1}});
            break;
        case 3:  // Mercator, true at TRUELAT1
            if (!truelat1) return unusable(name + " without TRUELAT1");
            wrf.mapping.name = "mercator";
            p.push_back({"longitude_of_projection_origin", {standLon.value_or(*cenLon)}});
            p.push_back({"standard_parallel", {*truelat1}});
            break;
        case 6: {  // cylindrical equidistant (lat-lon); rotated when POLE_LAT is not 90
            const double poleLat = global(file, "POLE_LAT").value_or(90.0);
            if (std::abs(poleLat - 90.0) > 1e-6) {
                return unusable("WRF rotated latitude-longitude (MAP_PROJ = 6, POLE_LAT = " +
                                numberText(poleLat) + ")");
            }
            wrf.mapping.name = "latitude_longitude";
            break;
        }
        default:
            return unusable(name);
    }
    p.push_back({"earth_radius", {kWrfEarthRadius}});
    p.push_back({"wrf_map_proj", {*mapProj}});
    wrf.usable = true;
    return wrf;
}

namespace {

// XLAT and XLONG at the first time, over south_north x west_east of the mass grid (x fastest);
// empty when the file lacks them or their shape is not that grid's.
// Metres along the equator of WRF's sphere per degree (lat-lon grids' DX and DY are metres).
constexpr double kMetresPerDegree = kWrfEarthRadius * std::numbers::pi / 180.0;

struct MassLonLat {
    std::vector<double> longitudes, latitudes;
};

MassLonLat readMassLonLat(const NetcdfFile& file, std::size_t nx, std::size_t ny) {
    const auto read = [&](const char* name) -> std::vector<double> {
        const NcVariable* var = file.findVariable(name);
        if (var == nullptr || var->dimIds.size() < 2) return {};
        const std::size_t rank = var->dimIds.size();
        const NcDimension& yDim = file.dimension(var->dimIds[rank - 2]);
        const NcDimension& xDim = file.dimension(var->dimIds[rank - 1]);
        if (yDim.name != "south_north" || xDim.name != "west_east" || yDim.size != ny ||
            xDim.size != nx) {
            return {};
        }
        std::vector<std::size_t> start(rank, 0), count(rank, 1);
        count[rank - 2] = ny;
        count[rank - 1] = nx;
        for (std::size_t d = 0; d + 2 < rank; ++d) {
            if (file.dimension(var->dimIds[d]).size == 0) return {};
        }
        return file.readDoubles(*var, start, count);
    };
    MassLonLat result{read("XLONG"), read("XLAT")};
    if (result.longitudes.empty() || result.latitudes.empty()) return {};
    return result;
}

WrfProjection unplaced(WrfProjection wrf, const std::string& reason) {
    wrf.mapping.name = reason;
    wrf.mapping.parameters = {{"wrf_map_proj", {*wrf.mapping.parameter("wrf_map_proj")}},
                              {"wrf_unplaced", {1.0}}};
    wrf.usable = false;
    return wrf;
}

// The worst distance, in cells, between XLAT/XLONG and the mass grid's places, and where.
struct Misplacement {
    double cells = 0.0;
    std::size_t i = 0, j = 0;
};

Misplacement worstMisplacement(const WrfProjection& wrf, const MassLonLat& lonLat, std::size_t nx) {
    const bool degrees = wrf.mapping.name == "latitude_longitude";
    const double dx = degrees ? wrf.dx / kMetresPerDegree : wrf.dx;
    const double dy = degrees ? wrf.dy / kMetresPerDegree : wrf.dy;
    std::vector<glm::dvec2> points(lonLat.longitudes.size());
    for (std::size_t n = 0; n < points.size(); ++n) {
        points[n] = {lonLat.longitudes[n], lonLat.latitudes[n]};
    }
    if (degrees) {
        const glm::dvec2 origin = points.front();
        for (glm::dvec2& q : points) q = {std::remainder(q.x - origin.x, 360.0), q.y - origin.y};
    } else {
        projectLonLat(projStringFor(wrf.mapping), points);
    }
    Misplacement worst;
    for (std::size_t n = 0; n < points.size(); ++n) {
        const std::size_t i = n % nx;
        const std::size_t j = n / nx;
        const double cells = std::max(std::abs(points[n].x - static_cast<double>(i) * dx) / dx,
                                      std::abs(points[n].y - static_cast<double>(j) * dy) / dy);
        // NaN (no image) counts as the worst of all.
        if (!(cells <= worst.cells)) worst = {std::isnan(cells) ? HUGE_VAL : cells, i, j};
    }
    return worst;
}

}  // namespace

void placeWrfGrid(const NetcdfFile& file, WrfProjection& wrf, Axis& x, bool xStaggered, Axis& y,
                  bool yStaggered) {
    if (!wrf.usable) return;
    const std::size_t nx = x.size() - (xStaggered ? 1 : 0);
    const std::size_t ny = y.size() - (yStaggered ? 1 : 0);
    const std::string name = "WRF MAP_PROJ = " + numberText(*wrf.mapping.parameter("wrf_map_proj"));
    const bool degrees = wrf.mapping.name == "latitude_longitude";

    // The anchor: the mass point at index (i0, j0) lies at (lon0, lat0).
    double i0 = 0.0, j0 = 0.0, lon0 = 0.0, lat0 = 0.0;
    const MassLonLat lonLat = readMassLonLat(file, nx, ny);
    if (!lonLat.longitudes.empty()) {
        lon0 = lonLat.longitudes.front();
        lat0 = lonLat.latitudes.front();
    } else {
        const auto domain = [&](const char* key) -> std::optional<std::size_t> {
            const auto v = global(file, key);
            if (!v || *v < 2.0) return std::nullopt;
            return static_cast<std::size_t>(std::lround(*v)) - 1;  // staggered count - 1
        };
        const auto domainX = domain("WEST-EAST_GRID_DIMENSION");
        const auto domainY = domain("SOUTH-NORTH_GRID_DIMENSION");
        if ((domainX && *domainX != nx) || (domainY && *domainY != ny)) {
            wrf = unplaced(
                wrf, name + ": the file holds " + std::to_string(nx) + " x " + std::to_string(ny) +
                         " points of its domain's " + std::to_string(domainX.value_or(nx)) + " x " +
                         std::to_string(domainY.value_or(ny)) + " and no XLAT/XLONG to say which");
            return;
        }
        i0 = 0.5 * static_cast<double>(nx - 1);
        j0 = 0.5 * static_cast<double>(ny - 1);
        lon0 = wrf.centreLongitude;
        lat0 = wrf.centreLatitude;
    }
    if (!degrees) {
        wrf.mapping.parameters.push_back({"origin_longitude", {lon0}});
        wrf.mapping.parameters.push_back({"origin_latitude", {lat0}});
    }
    if (!lonLat.longitudes.empty()) {
        Misplacement worst;
        try {
            worst = worstMisplacement(wrf, lonLat, nx);
        } catch (const Error& e) {
            wrf = unplaced(wrf, name + ": " + e.what());
            return;
        }
        if (worst.cells > kWrfPlacementTolerance) {
            const std::size_t n = worst.j * nx + worst.i;
            std::ostringstream why;
            why.precision(4);
            why << name << ": the file's XLAT/XLONG at point (" << worst.i << ", " << worst.j
                << ") = (" << lonLat.latitudes[n] << " N, " << lonLat.longitudes[n] << " E) lie "
                << worst.cells
                << " cells from where its map attributes (MAP_PROJ, TRUELAT1, TRUELAT2, "
                   "STAND_LON, DX, DY) put that point; the grid is not placed on the map";
            wrf = unplaced(wrf, why.str());
            return;
        }
    }

    const auto fill = [](Axis& axis, bool staggered, double origin, double step, double base) {
        const double shift = origin + (staggered ? 0.5 : 0.0);
        for (std::size_t i = 0; i < axis.size(); ++i) {
            axis.values[i] = base + (static_cast<double>(i) - shift) * step;
        }
    };
    if (degrees) {
        fill(x, xStaggered, i0, wrf.dx / kMetresPerDegree, lon0);
        fill(y, yStaggered, j0, wrf.dy / kMetresPerDegree, lat0);
        x.units = "degrees_east";
        x.standardName = "longitude";
        y.units = "degrees_north";
        y.standardName = "latitude";
        return;
    }
    fill(x, xStaggered, i0, wrf.dx, 0.0);
    fill(y, yStaggered, j0, wrf.dy, 0.0);
    x.units = y.units = "m";
    x.standardName = "projection_x_coordinate";
    y.standardName = "projection_y_coordinate";
}

}  // namespace ensil::data

#include "geo/map_projection.h"

#include <proj.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <locale>
#include <sstream>
#include <string_view>

#include "data/error.h"

namespace ensil::geo {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// Written with the C locale and every digit a double has, so the string means the same on
// every machine.
std::string number(double value) {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out.precision(17);
    out << value;
    return out.str();
}

template <std::size_t N>
bool oneOf(const std::string& value, const std::array<std::string_view, N>& options) {
    return std::find(options.begin(), options.end(), value) != options.end();
}

// CF: a longitude axis has standard_name longitude or units degrees_east (and spellings);
// plain "degrees" counts when the axis is named like one.
bool isLongitude(const data::Axis& axis) {
    const std::string units = lower(axis.units);
    const std::string name = lower(axis.name);
    return axis.standardName == "longitude" ||
           oneOf(units, std::array<std::string_view, 6>{"degrees_east", "degree_east", "degree_e",
                                                        "degrees_e", "degreee", "degreese"}) ||
           (units.starts_with("degree") &&
            oneOf(name, std::array<std::string_view, 3>{"lon", "longitude", "long"}));
}

bool isLatitude(const data::Axis& axis) {
    const std::string units = lower(axis.units);
    const std::string name = lower(axis.name);
    return axis.standardName == "latitude" ||
           oneOf(units, std::array<std::string_view, 6>{"degrees_north", "degree_north", "degree_n",
                                                        "degrees_n", "degreen", "degreesn"}) ||
           (units.starts_with("degree") &&
            oneOf(name, std::array<std::string_view, 2>{"lat", "latitude"}));
}

double metresPerUnit(const std::string& units) {
    const std::string u = lower(units);
    if (oneOf(u, std::array<std::string_view, 5>{"km", "kilometre", "kilometres", "kilometer",
                                                 "kilometers"})) {
        return 1000.0;
    }
    return 1.0;  // CF projection coordinates are in metres unless they say otherwise
}

// The figure of the Earth, from the CF attributes that describe it; WGS 84 when none does.
std::string earthShape(const data::GridMapping& m) {
    if (const auto radius = m.parameter("earth_radius")) return " +R=" + number(*radius);
    if (const auto a = m.parameter("semi_major_axis")) {
        if (const auto rf = m.parameter("inverse_flattening"); rf && *rf > 0.0) {
            return " +a=" + number(*a) + " +rf=" + number(*rf);
        }
        if (const auto b = m.parameter("semi_minor_axis")) {
            return " +a=" + number(*a) + " +b=" + number(*b);
        }
        return " +R=" + number(*a);
    }
    return " +ellps=WGS84";
}

// The string for m with false easting and northing x0, y0 (metres).
std::string projStringWith(const data::GridMapping& m, double x0, double y0);

// The projected x, y (metres) of a longitude/latitude through a PROJ string; NaN where PROJ
// has none.
glm::dvec2 projectedPoint(const std::string& projString, double lon, double lat) {
    const std::string pipeline =
        "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad +step " + projString;
    PJ_CONTEXT* context = proj_context_create();
    PJ* transformation = proj_create(context, pipeline.c_str());
    glm::dvec2 result(kNaN);
    if (transformation != nullptr) {
        const PJ_COORD out = proj_trans(transformation, PJ_FWD, proj_coord(lon, lat, 0.0, 0.0));
        if (std::isfinite(out.xy.x) && std::isfinite(out.xy.y) && std::abs(out.xy.x) < HUGE_VAL) {
            result = {out.xy.x, out.xy.y};
        }
        proj_destroy(transformation);
    }
    proj_context_destroy(context);
    return result;
}

}  // namespace

std::string projStringFor(const data::GridMapping& m) {
    // A grid whose x, y origin is a point on the Earth (WRF's domain centre, not a CF
    // attribute): the false easting and northing put that point's image at (0, 0).
    const auto centreLon = m.parameter("centre_longitude");
    const auto centreLat = m.parameter("centre_latitude");
    if (centreLon && centreLat) {
        const glm::dvec2 centre =
            projectedPoint(projStringWith(m, 0.0, 0.0), *centreLon, *centreLat);
        if (!std::isfinite(centre.x)) {
            throw data::Error(data::ErrorKind::UnsupportedFormat,
                              "grid mapping '" + m.name + "' has no image of its centre (" +
                                  number(*centreLon) + ", " + number(*centreLat) + ")");
        }
        return projStringWith(m, -centre.x, -centre.y);
    }
    return projStringWith(m, m.parameter("false_easting").value_or(0.0),
                          m.parameter("false_northing").value_or(0.0));
}

namespace {

std::string projStringWith(const data::GridMapping& m, double x0, double y0) {
    const auto need = [&m](const char* key) {
        const auto value = m.parameter(key);
        if (!value || !std::isfinite(*value)) {
            throw data::Error(data::ErrorKind::UnsupportedFormat,
                              "grid mapping '" + m.name + "' has no numeric '" + key +
                                  "' attribute, which it needs");
        }
        return *value;
    };
    const auto optional = [&m](const char* key, double fallback) {
        return m.parameter(key).value_or(fallback);
    };
    const std::string offsets = " +x_0=" + number(x0) + " +y_0=" + number(y0);
    // The CF attribute names and their PROJ parameters follow CF appendix F and PROJ's
    // operation pages; GDAL maps them the same way.
    if (m.name == "rotated_latitude_longitude") {
        return "+proj=ob_tran +o_proj=longlat +o_lon_p=" +
               number(optional("north_pole_grid_longitude", 0.0)) +
               " +o_lat_p=" + number(need("grid_north_pole_latitude")) +
               " +lon_0=" + number(180.0 + need("grid_north_pole_longitude"));
    }
    if (m.name == "lambert_conformal_conic") {
        const double first = need("standard_parallel");
        const double second = m.parameter("standard_parallel", 1).value_or(first);
        return "+proj=lcc +lat_1=" + number(first) + " +lat_2=" + number(second) +
               " +lat_0=" + number(optional("latitude_of_projection_origin", first)) +
               " +lon_0=" + number(need("longitude_of_central_meridian")) + offsets + earthShape(m);
    }
    if (m.name == "polar_stereographic") {
        const std::string scale =
            m.parameter("standard_parallel")
                ? " +lat_ts=" + number(need("standard_parallel"))
                : " +k_0=" + number(optional("scale_factor_at_projection_origin", 1.0));
        return "+proj=stere +lat_0=" + number(need("latitude_of_projection_origin")) +
               " +lon_0=" + number(need("straight_vertical_longitude_from_pole")) + scale +
               offsets + earthShape(m);
    }
    if (m.name == "mercator") {
        const std::string scale =
            m.parameter("standard_parallel")
                ? " +lat_ts=" + number(need("standard_parallel"))
                : " +k_0=" + number(optional("scale_factor_at_projection_origin", 1.0));
        return "+proj=merc +lon_0=" + number(optional("longitude_of_projection_origin", 0.0)) +
               scale + offsets + earthShape(m);
    }
    if (m.name == "transverse_mercator") {
        return "+proj=tmerc +lat_0=" + number(optional("latitude_of_projection_origin", 0.0)) +
               " +lon_0=" + number(need("longitude_of_central_meridian")) +
               " +k_0=" + number(optional("scale_factor_at_central_meridian", 1.0)) + offsets +
               earthShape(m);
    }
    if (m.parameter("wrf_map_proj")) {
        throw data::Error(data::ErrorKind::UnsupportedFormat,
                          "'" + m.name +
                              "' is not a map projection ensil reads: of WRF's it reads "
                              "MAP_PROJ 1 (Lambert conformal), 2 (polar stereographic), "
                              "3 (Mercator) and 6 (latitude-longitude, unrotated), with "
                              "CEN_LAT, CEN_LON, DX and DY");
    }
    throw data::Error(data::ErrorKind::UnsupportedFormat,
                      "grid mapping '" + m.name +
                          "' is not one ensil reads (it reads latitude_longitude, "
                          "rotated_latitude_longitude, lambert_conformal_conic, "
                          "polar_stereographic, mercator and transverse_mercator)");
}

}  // namespace

struct MapProjection::Proj {
    PJ_CONTEXT* context = nullptr;
    PJ* transformation = nullptr;
    Proj() = default;
    Proj(const Proj&) = delete;
    Proj& operator=(const Proj&) = delete;
    ~Proj() {
        if (transformation != nullptr) proj_destroy(transformation);
        if (context != nullptr) proj_context_destroy(context);
    }
    // Transforms in place; PROJ marks a point it cannot transform with HUGE_VAL.
    void transform(std::vector<glm::dvec2>& points, PJ_DIRECTION direction) const {
        if (points.empty()) return;
        proj_trans_generic(transformation, direction, &points[0].x, sizeof(glm::dvec2),
                           points.size(), &points[0].y, sizeof(glm::dvec2), points.size(), nullptr,
                           0, 0, nullptr, 0, 0);
        for (glm::dvec2& p : points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) >= HUGE_VAL) {
                p = glm::dvec2(kNaN);
            }
        }
    }
};

MapProjection::MapProjection(MapProjection&&) noexcept = default;
MapProjection& MapProjection::operator=(MapProjection&&) noexcept = default;
MapProjection::~MapProjection() = default;

MapProjection MapProjection::forGrid(const data::Grid& grid, const data::GridMapping& mapping) {
    MapProjection result;
    result.m_xMiddle = 0.5 * (grid.x().minValue() + grid.x().maxValue());
    if (mapping.empty() || mapping.name == "latitude_longitude") {
        if (isLongitude(grid.x()) && isLatitude(grid.y())) {
            result.m_kind = Kind::LonLat;
        } else {
            result.m_reason = "the horizontal axes ('" + grid.x().name + "', '" + grid.y().name +
                              "') are not longitude and latitude, and no grid_mapping says "
                              "where they lie";
        }
        return result;
    }
    try {
        result.m_projString = projStringFor(mapping);
    } catch (const data::Error& e) {
        result.m_reason = e.what();
        return result;
    }
    const bool rotated = mapping.name == "rotated_latitude_longitude";
    // PROJ's projection steps take radians; a rotated grid's coordinates come back in radians
    // too and are turned into degrees, the units of its axes.
    const std::string pipeline =
        "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad "
        "+step " +
        result.m_projString + (rotated ? " +step +proj=unitconvert +xy_in=rad +xy_out=deg" : "");
    auto proj = std::make_unique<Proj>();
    proj->context = proj_context_create();
    proj->transformation = proj_create(proj->context, pipeline.c_str());
    if (proj->transformation == nullptr) {
        result.m_reason =
            "PROJ cannot use grid mapping '" + mapping.name + "' (" +
            proj_context_errno_string(proj->context, proj_context_errno(proj->context)) + ")";
        return result;
    }
    result.m_proj = std::move(proj);
    result.m_kind = rotated ? Kind::Rotated : Kind::Projected;
    result.m_metresPerUnit = rotated ? 1.0 : metresPerUnit(grid.x().units);
    return result;
}

void MapProjection::wrapX(std::vector<glm::dvec2>& points) const {
    for (glm::dvec2& p : points) p.x = m_xMiddle + std::remainder(p.x - m_xMiddle, 360.0);
}

void MapProjection::toGrid(std::vector<glm::dvec2>& points) const {
    switch (m_kind) {
        case Kind::None:
            std::fill(points.begin(), points.end(), glm::dvec2(kNaN));
            return;
        case Kind::LonLat:
            wrapX(points);
            return;
        case Kind::Rotated:
            m_proj->transform(points, PJ_FWD);
            wrapX(points);
            return;
        case Kind::Projected:
            m_proj->transform(points, PJ_FWD);
            for (glm::dvec2& p : points) p /= m_metresPerUnit;
            return;
    }
}

void MapProjection::toLonLat(std::vector<glm::dvec2>& points) const {
    switch (m_kind) {
        case Kind::None:
            std::fill(points.begin(), points.end(), glm::dvec2(kNaN));
            return;
        case Kind::LonLat:
            return;
        case Kind::Rotated:
            m_proj->transform(points, PJ_INV);
            return;
        case Kind::Projected:
            for (glm::dvec2& p : points) p *= m_metresPerUnit;
            m_proj->transform(points, PJ_INV);
            return;
    }
}

}  // namespace ensil::geo

#include "data/proj_definition.h"

#include <proj.h>

#include <cmath>
#include <limits>
#include <locale>
#include <sstream>

#include "data/error.h"

namespace ensil::data {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Written with the C locale and every digit a double has, so the string means the same on
// every machine.
std::string number(double value) {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out.precision(17);
    out << value;
    return out.str();
}

// The figure of the Earth, from the CF attributes that describe it; WGS 84 when none does.
std::string earthShape(const GridMapping& m) {
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
std::string projStringWith(const GridMapping& m, double x0, double y0);

}  // namespace

std::string projStringFor(const GridMapping& m) {
    // A grid whose x, y origin is a point on the Earth (a WRF grid's anchor, not a CF
    // attribute): the false easting and northing put that point's image at (0, 0).
    const auto originLon = m.parameter("origin_longitude");
    const auto originLat = m.parameter("origin_latitude");
    if (originLon && originLat) {
        std::vector<glm::dvec2> origin{{*originLon, *originLat}};
        projectLonLat(projStringWith(m, 0.0, 0.0), origin);
        if (!std::isfinite(origin[0].x)) {
            throw Error(ErrorKind::UnsupportedFormat,
                        "grid mapping '" + m.name + "' has no image of its origin (" +
                            number(*originLon) + ", " + number(*originLat) + ")");
        }
        return projStringWith(m, -origin[0].x, -origin[0].y);
    }
    return projStringWith(m, m.parameter("false_easting").value_or(0.0),
                          m.parameter("false_northing").value_or(0.0));
}

void projectLonLat(const std::string& projString, std::vector<glm::dvec2>& points) {
    if (points.empty()) return;
    const std::string pipeline =
        "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad +step " + projString;
    PJ_CONTEXT* context = proj_context_create();
    PJ* transformation = proj_create(context, pipeline.c_str());
    if (transformation == nullptr) {
        const std::string why = proj_context_errno_string(context, proj_context_errno(context));
        proj_context_destroy(context);
        throw Error(ErrorKind::UnsupportedFormat,
                    "PROJ cannot use '" + projString + "' (" + why + ")");
    }
    proj_trans_generic(transformation, PJ_FWD, &points[0].x, sizeof(glm::dvec2), points.size(),
                       &points[0].y, sizeof(glm::dvec2), points.size(), nullptr, 0, 0, nullptr, 0,
                       0);
    for (glm::dvec2& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) >= HUGE_VAL) {
            p = glm::dvec2(kNaN);
        }
    }
    proj_destroy(transformation);
    proj_context_destroy(context);
}

namespace {

std::string projStringWith(const GridMapping& m, double x0, double y0) {
    const auto need = [&m](const char* key) {
        const auto value = m.parameter(key);
        if (!value || !std::isfinite(*value)) {
            throw Error(ErrorKind::UnsupportedFormat, "grid mapping '" + m.name +
                                                          "' has no numeric '" + key +
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
    if (m.name == "lambert_azimuthal_equal_area") {
        // The Met Office's UK grids and IMPROVER's, and EU-wide ones (ETRS89-LAEA).
        return "+proj=laea +lat_0=" + number(need("latitude_of_projection_origin")) +
               " +lon_0=" + number(need("longitude_of_projection_origin")) + offsets +
               earthShape(m);
    }
    if (m.name == "albers_conical_equal_area") {
        const double first = need("standard_parallel");
        const double second = m.parameter("standard_parallel", 1).value_or(first);
        return "+proj=aea +lat_1=" + number(first) + " +lat_2=" + number(second) +
               " +lat_0=" + number(optional("latitude_of_projection_origin", 0.0)) +
               " +lon_0=" + number(need("longitude_of_central_meridian")) + offsets + earthShape(m);
    }
    if (m.name == "stereographic") {
        return "+proj=stere +lat_0=" + number(need("latitude_of_projection_origin")) +
               " +lon_0=" + number(need("longitude_of_projection_origin")) +
               " +k_0=" + number(optional("scale_factor_at_projection_origin", 1.0)) + offsets +
               earthShape(m);
    }
    if (m.parameter("wrf_unplaced")) {
        // A WRF grid its own XLAT/XLONG contradict: the name says why (data/wrf_conventions.h).
        throw Error(ErrorKind::UnsupportedFormat, m.name);
    }
    if (m.parameter("wrf_map_proj")) {
        throw Error(ErrorKind::UnsupportedFormat,
                    "'" + m.name +
                        "' is not a map projection ensil reads: of WRF's it reads "
                        "MAP_PROJ 1 (Lambert conformal), 2 (polar stereographic), "
                        "3 (Mercator) and 6 (latitude-longitude, unrotated), with "
                        "CEN_LAT, CEN_LON, DX and DY");
    }
    throw Error(ErrorKind::UnsupportedFormat,
                "grid mapping '" + m.name +
                    "' is not one ensil reads (it reads latitude_longitude, "
                    "rotated_latitude_longitude, lambert_conformal_conic, "
                    "lambert_azimuthal_equal_area, albers_conical_equal_area, "
                    "polar_stereographic, stereographic, mercator and transverse_mercator)");
}

}  // namespace

}  // namespace ensil::data

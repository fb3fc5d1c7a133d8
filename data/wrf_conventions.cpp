#include "data/wrf_conventions.h"

#include <netcdf.h>

#include <cmath>
#include <numbers>
#include <sstream>

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
    p.push_back({"centre_longitude", {*cenLon}});
    p.push_back({"centre_latitude", {*cenLat}});
    p.push_back({"wrf_map_proj", {*mapProj}});
    wrf.usable = true;
    return wrf;
}

void applyWrfAxes(const WrfProjection& wrf, Axis& x, Axis& y) {
    const bool lonLat = wrf.mapping.name == "latitude_longitude";
    const double metresPerDegree = kWrfEarthRadius * std::numbers::pi / 180.0;
    const auto fill = [&](Axis& axis, double step, double centre) {
        const double middle = 0.5 * static_cast<double>(axis.size() - 1);
        for (std::size_t i = 0; i < axis.size(); ++i) {
            axis.values[i] = centre + (static_cast<double>(i) - middle) * step;
        }
    };
    if (lonLat) {
        fill(x, wrf.dx / metresPerDegree, *wrf.mapping.parameter("centre_longitude"));
        fill(y, wrf.dy / metresPerDegree, *wrf.mapping.parameter("centre_latitude"));
        x.units = "degrees_east";
        x.standardName = "longitude";
        y.units = "degrees_north";
        y.standardName = "latitude";
        return;
    }
    fill(x, wrf.dx, 0.0);
    fill(y, wrf.dy, 0.0);
    x.units = y.units = "m";
    x.standardName = "projection_x_coordinate";
    y.standardName = "projection_y_coordinate";
}

}  // namespace ensil::data

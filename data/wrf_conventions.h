// WRF output's own map attributes: global MAP_PROJ, TRUELAT1, TRUELAT2, STAND_LON, CEN_LAT,
// CEN_LON, DX, DY (and POLE_LAT for lat-lon grids) on grids whose x and y dimensions
// (west_east, south_north and their _stag forms) have no coordinate variables. Read here into a
// data::GridMapping with CF names and axes in metres from the domain's centre (METHODS.md
// section 16); the geo layer turns that into a PROJ transformation. Internal to data/; pure
// functions over an open file.
#pragma once

#include <optional>

#include "data/grid.h"
#include "data/grid_mapping.h"
#include "data/netcdf_file.h"

namespace ensil::data {

// WRF's sphere (its EARTH_RADIUS_M), metres.
inline constexpr double kWrfEarthRadius = 6370000.0;

struct WrfProjection {
    // The CF equivalent: lambert_conformal_conic (MAP_PROJ 1), polar_stereographic (2),
    // mercator (3), latitude_longitude (6, unrotated), each with earth_radius 6370000 and the
    // domain's centre as centre_longitude, centre_latitude. A MAP_PROJ ensil cannot use gets a
    // name "WRF MAP_PROJ = N" and the parameter wrf_map_proj, so the geo layer says why.
    GridMapping mapping;
    // Whether the x and y axes become map coordinates (metres, or degrees for lat-lon).
    bool usable = false;
    double dx = 0.0;  // metres (lat-lon: metres along the equator)
    double dy = 0.0;
};

// The WRF projection the file's global attributes describe; nullopt when it has no MAP_PROJ.
std::optional<WrfProjection> readWrfProjection(const NetcdfFile& file);

// Whether a dimension is one of WRF's horizontal ones (west_east, south_north, *_stag).
bool isWrfHorizontalDimension(const std::string& name);

// x_i = (i - (n - 1) / 2) DX in metres (lat-lon: CEN_LON + (i - (n - 1) / 2) DX / (R pi / 180)
// in degrees east), and likewise y; the axes' names are kept.
void applyWrfAxes(const WrfProjection& wrf, Axis& x, Axis& y);

}  // namespace ensil::data

// WRF output's own map attributes: global MAP_PROJ, TRUELAT1, TRUELAT2, STAND_LON, CEN_LAT,
// CEN_LON, DX, DY (and POLE_LAT for lat-lon grids) on grids whose x and y dimensions
// (west_east, south_north and their _stag forms) have no coordinate variables. Read here into a
// data::GridMapping with CF names and axes in metres on the map, anchored at the file's own
// XLAT/XLONG and checked against them (METHODS.md section 16); the geo layer turns that into a
// PROJ transformation. Internal to data/; pure functions over an open file (hold
// netcdfLibraryMutex() around them, as around every netCDF call).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "data/grid.h"
#include "data/grid_mapping.h"
#include "data/netcdf_file.h"

namespace ensil::data {

// WRF's sphere (its EARTH_RADIUS_M), metres.
inline constexpr double kWrfEarthRadius = 6370000.0;

// The largest distance, in grid cells, that a point of XLAT/XLONG may lie from where the map
// attributes put it before ensil refuses to place the grid on the map.
inline constexpr double kWrfPlacementTolerance = 0.1;

struct WrfProjection {
    // The CF equivalent: lambert_conformal_conic (MAP_PROJ 1), polar_stereographic (2),
    // mercator (3), latitude_longitude (6, unrotated), each with earth_radius 6370000. A
    // MAP_PROJ ensil cannot use gets a name "WRF MAP_PROJ = N" and the parameter wrf_map_proj,
    // so the geo layer says why; a grid that cannot be placed (placeWrfGrid) gets the reason
    // as its name and the parameter wrf_unplaced.
    GridMapping mapping;
    // Whether the x and y axes can become map coordinates (metres, or degrees for lat-lon).
    bool usable = false;
    double dx = 0.0;  // metres (lat-lon: metres along the equator)
    double dy = 0.0;
    double centreLongitude = 0.0;  // CEN_LON, CEN_LAT: the centre of the whole domain
    double centreLatitude = 0.0;
};

// The WRF projection the file's global attributes describe; nullopt when it has no MAP_PROJ.
std::optional<WrfProjection> readWrfProjection(const NetcdfFile& file);

// Whether a dimension is one of WRF's horizontal ones (west_east, south_north, *_stag).
bool isWrfHorizontalDimension(const std::string& name);

// WRF's Times(Time, DateStrLen) along `dim`, as ensil writes dates: "2016-10-06_12:00:00" is
// "2016-10-06T12:00". Empty when the file has no such variable along that dimension (or it
// cannot be read).
std::vector<std::string> wrfTimeLabels(const NetcdfFile& file, const NcDimension& dim);

// Places the grid's x and y (indices along west_east and south_north, or their _stag forms)
// on the map of a usable projection. The anchor is the file's own first mass point
// (XLONG[0, 0], XLAT[0, 0]), since a file may hold only part of its domain (CEN_LAT and CEN_LON
// describe the whole domain); mass point i lies at x = i DX, a staggered point half a cell
// before it. Every XLAT/XLONG point must then lie within kWrfPlacementTolerance cells of its
// place. Without XLAT/XLONG the domain's centre is the anchor, as long as the file covers the
// whole domain (WEST-EAST_GRID_DIMENSION and SOUTH-NORTH_GRID_DIMENSION, where present, say
// so). When the grid cannot be placed, wrf becomes unusable with the reason in its mapping's
// name, and the axes stay indices.
void placeWrfGrid(const NetcdfFile& file, WrfProjection& wrf, Axis& x, bool xStaggered, Axis& y,
                  bool yStaggered);

}  // namespace ensil::data

// The PROJ definition a CF grid mapping means (CF appendix F's attribute names to PROJ's
// operation parameters), and points carried through it. The geo/ layer builds its map
// projections from this string; the data layer needs it too, to check WRF's XLAT/XLONG against
// the grid its map attributes describe (data/wrf_conventions.h). Pure functions; any thread
// (each call has its own PROJ context).
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "data/grid_mapping.h"

namespace ensil::data {

// The PROJ string for a CF grid mapping (the longitude/latitude side in radians, as a PROJ
// pipeline step takes it), or an Error(UnsupportedFormat) naming the mapping and its missing
// attribute. With origin_longitude and origin_latitude (a WRF grid's anchor point, not a CF
// attribute) the false easting and northing are minus that point's projected x and y, so that
// the point lies at x = y = 0.
std::string projStringFor(const GridMapping& mapping);

// Longitudes and latitudes (degrees) to projected x, y (metres) through a PROJ string from
// projStringFor, in place; NaN where PROJ gives none. Throws Error(UnsupportedFormat) when PROJ
// refuses the string.
void projectLonLat(const std::string& projString, std::vector<glm::dvec2>& points);

}  // namespace ensil::data

// The region a data selection keeps (DataSelection::region): "-10,40,35,72" keeps the grid
// columns from 10 W to 40 E and the rows from 35 N to 72 N, edges included, so that a global
// 0.25-degree ensemble is read as Europe without cutting it with another tool first. LON0 > LON1
// is a box across the date line or the 0/360 seam ("350,20,35,70"): the longitudes kept then
// run continuously eastwards from LON0 (a 0..360 grid asked for -10..40 gives 350..359.75 as
// -10..-0.25, then 0..40; never past 360: 350..20 is written -10..20), so maps, coastlines and
// sections stay right. Only a regular
// longitude-latitude grid (1D longitude and latitude axes, no other grid mapping) can be cut
// so. Applied where every reader is called (data/ensemble_reader.cpp), as the levels kept are.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "data/error.h"
#include "data/grid.h"
#include "data/grid_mapping.h"

namespace ensil::data {

struct Region {
    double lon0 = 0.0;  // the western edge, degrees east
    double lon1 = 0.0;  // the eastern edge; below lon0: the box crosses the date line or seam
    double lat0 = 0.0;  // one latitude edge, degrees north (either way round)
    double lat1 = 0.0;

    bool operator==(const Region&) const = default;
};

// "LON0,LON1,LAT0,LAT1" in degrees ("-10,40,35,72", " 350, 20, 35, 70 "). Throws
// Error(InvalidArgument) saying what is wrong (not four numbers, a latitude outside -90..90, a
// longitude outside -360..360, a box of no width or height, or wider than the globe) and
// showing the form.
Region parseRegion(const std::string& text);
// The same checks on a region given as numbers (Python's bbox=(lon0, lon1, lat0, lat1)).
void checkRegion(const Region& region);
// "-10,40,35,72": parseRegion's form, read back as the same region.
std::string regionText(const Region& region);

// A run of consecutive grid columns, [first, first + count), whose longitudes are kept plus
// `shift` (a multiple of 360 degrees) so that the longitudes kept run on without a jump.
struct ColumnRun {
    std::size_t first = 0;
    std::size_t count = 0;
    double shift = 0.0;

    bool operator==(const ColumnRun&) const = default;
};

// The columns and rows of a grid that a region keeps: the runs of columns in the order kept
// (two where the box crosses the grid's seam), and the rows [firstRow, firstRow + rowCount).
struct HorizontalWindow {
    std::vector<ColumnRun> columns;
    std::size_t firstRow = 0;
    std::size_t rowCount = 0;

    [[nodiscard]] std::size_t columnCount() const;
    bool operator==(const HorizontalWindow&) const = default;
};

// The grid's columns and rows within `region`, edges included (within 1e-4 degrees, so that a
// coordinate stored as float still counts). Longitudes are compared modulo 360; the columns
// kept are ordered as the grid's longitudes run (eastwards for an increasing axis), each
// written as its longitude plus the multiple of 360 that puts it at or east of LON0, all a turn
// lower where the easternmost would lie past 360.
// Throws Error(InvalidArgument) naming `source` when the grid is not a regular
// longitude-latitude grid (a grid mapping other than latitude_longitude, or axes that are not
// longitude and latitude), and RegionOutsideGrid when fewer than 2 columns or rows lie within.
HorizontalWindow regionWithin(const Grid& grid, const GridMapping& mapping, const Region& region,
                              const std::string& source);

// The grid's columns and rows in `window`: the longitudes of its runs, shifted, and its rows'
// latitudes; z unchanged. Throws Error(InvalidArgument) when the window leaves the grid, holds
// fewer than 2 columns or rows, or its longitudes do not run one way.
Grid gridWindow(const Grid& grid, const HorizontalWindow& window);

// A region with no grid point, or too few (a volume needs 2 along each axis). A refused
// argument rather than unusable data: the command line exits with status 2 for it.
class RegionOutsideGrid : public Error {
public:
    explicit RegionOutsideGrid(const std::string& message)
        : Error(ErrorKind::InvalidArgument, message) {}
};

}  // namespace ensil::data

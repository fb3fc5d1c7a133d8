// Writes per-point ensemble statistics (those prep::computeEnsembleStatistics gives, METHODS.md
// section 17) as one CF-1.8 NetCDF file: float variables mean, stddev, min, max, range,
// exceedance_probability and member_count on the data's own (z, y, x) dimensions and
// coordinates, level_crossing_probability on the cell grid (dimensions <x>_cell, <y>_cell,
// <z>_cell, coordinates at the cell centres), NaN as _FillValue where a value is undefined, the
// grid mapping of a rotated or projected grid, and where the numbers came from in global
// attributes (isovalue, members, source, history). Callable from any thread; the caller owns
// the values.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "data/grid.h"
#include "data/grid_mapping.h"

namespace ensil::data {

struct StatisticsFile {
    // The statistics' variable, as the ensemble has it.
    std::string variable;  // e.g. "t"
    std::string longName;  // e.g. "Temperature"; may be empty
    std::string units;     // e.g. "K"; may be empty
    Grid grid;
    GridMapping gridMapping;                   // written when not empty
    std::vector<std::string> fixedDimensions;  // e.g. "time = 0 of 4 (2017-01-01T00:00)"
    float isovalue = 0.0F;                     // c of P(f > c) and the level crossing
    // What the members run along, named in the CF cell_methods ("time: mean"): empty for an
    // ensemble's realizations ("realization: mean"); the dimension a user named as the members'
    // (forecast times, months) otherwise.
    std::string memberAxis;
    std::vector<std::string> members;  // the names of the members summarised
    std::vector<std::string> sources;  // the input files
    std::string history;               // how the file was made (the command line)

    // grid.pointCount() values each, x fastest; NaN where undefined.
    std::span<const float> count, mean, stddev, minimum, maximum, range, exceedance;
    // (nx - 1) (ny - 1) (nz - 1) values, the cell with lowest corner (i, j, k) at
    // i + (nx - 1) (j + (ny - 1) k).
    std::span<const float> levelCrossing;
};

// One float variable of the file: its name, values, units and long_name, and the CF cell
// method over the members that made it (empty for counts and probabilities).
struct StatisticsField {
    const char* name;
    std::span<const float> values;
    std::string units;
    std::string longName;
    std::string cellMethods;
    bool onCells = false;  // on the cell grid (the level-crossing probability)
};

// Every variable the file holds, in the order written: the one table of names and attributes.
std::vector<StatisticsField> statisticsFields(const StatisticsFile& file);

// The name of the dimension and coordinate variable of cell centres along an axis: "lon_cell".
std::string cellDimensionName(const Axis& axis);

// The cell centres along an axis: the mean of each two neighbouring coordinates.
std::vector<double> cellCentres(const Axis& axis);

// Throws Error(InvalidArgument) when a field's size does not match the grid (no file is made)
// and Error(WriteFailed) naming the file and the netCDF library's reason; a failed write
// removes the partial file.
void writeStatisticsNetcdf(const StatisticsFile& file, const std::string& path);

}  // namespace ensil::data

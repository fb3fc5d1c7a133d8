// Turns a NetCDF variable (or the derived wind speed) into a plan for reading it as an
// ensemble: which dimension holds members, which are x, y and z, which are fixed to an index,
// the grid, and how to unpack and mask values. Internal to data/; used by NetcdfReader.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "data/ensemble_reader.h"
#include "data/grid_mapping.h"
#include "data/netcdf_file.h"

namespace ensil::data {

// One stored variable that contributes to the ensemble (two for wind speed: u and v).
struct NcComponent {
    const NcVariable* variable = nullptr;
    std::array<int, 3> spatialDims{-1, -1, -1};  // dimension ids of x, y, z
    std::array<std::size_t, 3> sizes{};          // their sizes (one more where staggered)
};

struct NcPlan {
    std::string name;  // what the user selects: a variable name or "wind_speed"
    std::string longName;
    std::string units;
    bool derived = false;
    // Added to every value read: 300 K for the potential temperature derived from WRF's T (its
    // perturbation from 300 K). 0 otherwise.
    double offset = 0.0;
    std::vector<NcComponent> components;
    int memberDim = -1;  // dimension id, -1 when the file holds one member
    std::string memberReason;
    std::size_t timeIndex = 0;  // index taken along every other dimension
    Grid grid;                  // the mass grid (after destaggering)
    // The horizontal axes' map projection: the CF grid_mapping, else WRF's global attributes
    // (which also turn WRF's index axes into metres, data/wrf_conventions.h).
    GridMapping gridMapping;
};

// Everything usable or not in the file, in file order, derived variables last.
std::vector<VariableInfo> listVariables(const NetcdfFile& file, const std::string& memberDim);

// The plan for the selected variable (or the first usable one). Throws Error:
// VariableNotFound (listing candidates), NotThreeDimensional, MemberDimensionNotFound (only
// when requireMemberDim), InvalidArgument (time index past the end).
NcPlan planVariable(const NetcdfFile& file, const DataSelection& selection, bool requireMemberDim);

// "time = 0 of 4 (2017-01-01T00:00)" for each dimension fixed to an index.
std::vector<std::string> describeFixedDimensions(const NetcdfFile& file, const NcPlan& plan);
// The steps the time index picks from: named after the first fixed dimension, as many as the
// shortest fixed dimension has (the one index is taken along all of them), labelled with the
// first one's dates where its coordinate has CF time units, else with the index.
TimeSteps describeTimeSteps(const NetcdfFile& file, const NcPlan& plan);

// Member names: from the member coordinate (dates for time-like ones), else "member N".
std::vector<std::string> memberNames(const NetcdfFile& file, const NcPlan& plan);

}  // namespace ensil::data

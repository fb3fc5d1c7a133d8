// Turns a GRIB file's messages (data/grib_messages.h) into variables and a plan for reading
// one of them as an ensemble: which message holds each member's level at the selected time,
// the grid, member names and the fixed dimension. Internal to data/; used by GribReader.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "data/ensemble_reader.h"
#include "data/grib_messages.h"

namespace ensil::data {

struct GribPlan {
    std::string name;  // what the user selects: a variable name or "wind_speed"
    std::string longName;
    std::string units;
    bool derived = false;         // wind_speed: component 0 is u, component 1 is v
    std::string memberDimension;  // "number", or "time" when the user chose it
    std::string memberReason;
    std::vector<std::string> memberNames;
    std::vector<std::string> fixedDimensions;
    TimeSteps timeSteps;     // validity times; member indices when times are the members
    bool oneMember = false;  // the file holds one member (a single forecast)
    Grid grid;
    // fields[member][level] = the message of each component (u, v for wind_speed).
    std::vector<std::vector<std::array<const GribMessage*, 2>>> fields;
};

// Every variable in the file, in file order, derived ones last.
std::vector<VariableInfo> listGribVariables(const GribInventory& inventory,
                                            const std::string& path);

// The plan for the selected variable (or the usable one with the most levels). Throws Error:
// VariableNotFound (listing the usable ones), NotThreeDimensional, UnsupportedFormat (a grid
// ensil does not read, with the regridding command), MemberDimensionNotFound, InvalidArgument
// (time index past the end), CorruptFile (a field missing or given twice).
GribPlan planGribVariable(const GribInventory& inventory, const std::string& path,
                          const DataSelection& selection);

}  // namespace ensil::data

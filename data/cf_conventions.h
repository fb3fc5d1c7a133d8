// How ensil reads meaning into NetCDF dimensions, following the CF conventions first and common
// names second: which dimension is longitude-like (X), latitude-like (Y), vertical (Z), time, or
// the ensemble member, and why. Also turns CF time coordinates ("hours since 2017-1-1") into
// readable dates. Internal to data/; pure functions over an open file.
#pragma once

#include <optional>
#include <string>

#include "data/grid_mapping.h"
#include "data/netcdf_file.h"

namespace ensil::data {

enum class AxisRole { X, Y, Z, Time, Other };

// The role of a dimension, from its coordinate variable's attributes or its name.
AxisRole classifyDimension(const NetcdfFile& file, const NcDimension& dim);

struct MemberDimensionGuess {
    const NcDimension* dimension = nullptr;
    std::string reason;  // e.g. "coordinate variable 'number' has standard_name = realization"
};

// Finds the member dimension by, in order: a coordinate variable with standard_name
// realization or ensemble_member_id; _CoordinateAxisType = Ensemble; a dimension named
// number, member, members, realization, ens, ens0 or ensemble. Only dimensions of `var` count.
MemberDimensionGuess findMemberDimension(const NetcdfFile& file, const NcVariable& var);

// "2017-01-01T06:00" for value 6 with units "hours since 2017-1-1 00:00:00", in any CF calendar
// (data/cf_calendar.h: standard, gregorian, proleptic_gregorian, julian, noleap, 365_day,
// all_leap, 366_day, 360_day); nullopt when the units are not a CF time in seconds, minutes,
// hours or days, the calendar is not CF's, the epoch is not a date of the calendar, or the date
// falls outside the years 1 to 9999.
std::optional<std::string> formatCfTime(double value, const std::string& units,
                                        const std::string& calendar = "standard");

// The grid mapping `var` names in its `grid_mapping` attribute (the CF name and the mapping
// variable's numeric attributes); empty when it names none, or names a variable that is not
// in the file or has no grid_mapping_name.
GridMapping readGridMapping(const NetcdfFile& file, const NcVariable& var);

// True for units that name a length (m, km, metres...).
bool isLengthUnit(const std::string& units);

}  // namespace ensil::data

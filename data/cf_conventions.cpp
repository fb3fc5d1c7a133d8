#include "data/cf_conventions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <regex>
#include <string_view>

#include "data/ascii_case.h"
#include "data/cf_calendar.h"
#include "data/grid.h"

namespace ensil::data {
namespace {

template <std::size_t N>
bool oneOf(const std::string& value, const std::array<std::string_view, N>& options) {
    return std::find(options.begin(), options.end(), value) != options.end();
}

constexpr std::array<std::string_view, 10> kXNames{
    "lon",  "longitude", "x",    "west_east",      "west_east_stag",
    "nlon", "xc",        "rlon", "grid_longitude", "lon_0"};
constexpr std::array<std::string_view, 10> kYNames{
    "lat",  "latitude", "y",    "south_north",   "south_north_stag",
    "nlat", "yc",       "rlat", "grid_latitude", "lat_0"};
constexpr std::array<std::string_view, 15> kZNames{"level",
                                                   "plev",
                                                   "lev",
                                                   "z",
                                                   "bottom_top",
                                                   "bottom_top_stag",
                                                   "model_level_number",
                                                   "height",
                                                   "altitude",
                                                   "depth",
                                                   "pressure",
                                                   "isobaric",
                                                   "levelist",
                                                   "pressure_level",
                                                   "isobaricinhpa"};
constexpr std::array<std::string_view, 8> kTimeNames{
    "time", "t", "frtime", "month", "valid_time", "step", "times", "forecast_time"};
constexpr std::array<std::string_view, 7> kMemberNames{"number", "member", "members", "realization",
                                                       "ens",    "ens0",   "ensemble"};

std::optional<AxisRole> roleFromAttributes(const NetcdfFile& file, const NcVariable& coord) {
    const std::string axis = asciiLower(file.text(coord.id, "axis"));
    if (axis == "x") return AxisRole::X;
    if (axis == "y") return AxisRole::Y;
    if (axis == "z") return AxisRole::Z;
    if (axis == "t") return AxisRole::Time;
    const std::string standard = asciiLower(file.text(coord.id, "standard_name"));
    if (standard == "longitude" || standard == "grid_longitude" ||
        standard == "projection_x_coordinate") {
        return AxisRole::X;
    }
    if (standard == "latitude" || standard == "grid_latitude" ||
        standard == "projection_y_coordinate") {
        return AxisRole::Y;
    }
    if (standard == "time" || standard == "forecast_period" ||
        standard == "forecast_reference_time") {
        return AxisRole::Time;
    }
    if (standard == "air_pressure" || standard == "altitude" || standard == "height" ||
        standard == "depth" || standard == "model_level_number" ||
        standard.starts_with("atmosphere_") || standard.starts_with("ocean_")) {
        return AxisRole::Z;
    }
    const std::string units = asciiLower(file.text(coord.id, "units"));
    if (units == "degrees_east" || units == "degree_east" || units == "degrees_e") {
        return AxisRole::X;
    }
    if (units == "degrees_north" || units == "degree_north" || units == "degrees_n") {
        return AxisRole::Y;
    }
    if (units.find(" since ") != std::string::npos) return AxisRole::Time;
    if (isPressureUnit(units) || file.textAttribute(coord.id, "positive")) return AxisRole::Z;
    return std::nullopt;
}

}  // namespace

AxisRole classifyDimension(const NetcdfFile& file, const NcDimension& dim) {
    if (const NcVariable* coord = file.coordinateVariable(dim)) {
        if (auto role = roleFromAttributes(file, *coord)) return *role;
    }
    const std::string name = asciiLower(dim.name);
    if (oneOf(name, kXNames)) return AxisRole::X;
    if (oneOf(name, kYNames)) return AxisRole::Y;
    if (oneOf(name, kZNames)) return AxisRole::Z;
    if (oneOf(name, kTimeNames)) return AxisRole::Time;
    return AxisRole::Other;
}

MemberDimensionGuess findMemberDimension(const NetcdfFile& file, const NcVariable& var) {
    for (int id : var.dimIds) {
        const NcDimension& dim = file.dimension(id);
        if (const NcVariable* coord = file.coordinateVariable(dim)) {
            const std::string standard = file.text(coord->id, "standard_name");
            if (standard == "realization" || standard == "ensemble_member_id") {
                return {&dim,
                        "coordinate variable '" + dim.name + "' has standard_name = " + standard};
            }
        }
    }
    for (int id : var.dimIds) {
        const NcDimension& dim = file.dimension(id);
        if (const NcVariable* coord = file.coordinateVariable(dim)) {
            if (file.text(coord->id, "_CoordinateAxisType") == "Ensemble") {
                return {&dim, "coordinate variable '" + dim.name +
                                  "' has _CoordinateAxisType = Ensemble"};
            }
        }
    }
    for (int id : var.dimIds) {
        const NcDimension& dim = file.dimension(id);
        if (oneOf(asciiLower(dim.name), kMemberNames)) {
            return {&dim, "dimension named '" + dim.name + "'"};
        }
    }
    return {};
}

std::optional<std::string> formatCfTime(double value, const std::string& units,
                                        const std::string& calendar) {
    const std::optional<CfCalendar> cal = cfCalendar(calendar);
    if (!cal) return std::nullopt;
    static const std::regex pattern(
        R"(^\s*(seconds?|minutes?|hours?|days?)\s+since\s+(-?\d{1,4})-(\d{1,2})-(\d{1,2})(?:[ T](\d{1,2}):(\d{1,2})(?::(\d{1,2})(?:\.\d*)?)?)?.*$)",
        std::regex::icase);
    std::smatch m;
    if (!std::regex_match(units, m, pattern) || !std::isfinite(value)) return std::nullopt;
    const std::string unit = asciiLower(m[1].str());
    const double secondsPerUnit = unit.starts_with("second")   ? 1.0
                                  : unit.starts_with("minute") ? 60.0
                                  : unit.starts_with("hour")   ? 3600.0
                                                               : 86400.0;
    const std::optional<std::int64_t> epochDay =
        cfDayNumber(*cal, {std::stoi(m[2].str()), std::stoi(m[3].str()), std::stoi(m[4].str())});
    if (!epochDay) return std::nullopt;
    // A file can give any double: beyond some 19,000 years of the epoch there is no date to
    // print, and the sums below would overflow.
    const double offset = value * secondsPerUnit;
    if (std::abs(offset) > 6e11) return std::nullopt;
    constexpr std::int64_t kDay = 86'400;
    const std::int64_t seconds = (m[5].matched ? std::stoll(m[5].str()) * 3600 : 0) +
                                 (m[6].matched ? std::stoll(m[6].str()) * 60 : 0) +
                                 (m[7].matched ? std::stoll(m[7].str()) : 0) + std::llround(offset);
    const std::int64_t dayShift = seconds >= 0 ? seconds / kDay : -((-seconds + kDay - 1) / kDay);
    const std::int64_t ofDay = seconds - dayShift * kDay;
    const CfDate date = cfDateOf(*cal, *epochDay + dayShift);
    // Years before 1 are numbered differently by different tools (with or without a year 0).
    if (date.year < 1 || date.year > 9999) return std::nullopt;
    std::array<char, 64> text{};
    std::snprintf(text.data(), text.size(), "%04d-%02d-%02dT%02d:%02d", static_cast<int>(date.year),
                  date.month, date.day, static_cast<int>(ofDay / 3600),
                  static_cast<int>(ofDay % 3600 / 60));
    return std::string(text.data());
}

GridMapping readGridMapping(const NetcdfFile& file, const NcVariable& var) {
    // The CF form "name" is the usual one; the extended form "name: coord1 coord2" names the
    // mapping first, which is all that is needed here.
    std::string mappingName = file.text(var.id, "grid_mapping");
    mappingName = mappingName.substr(0, mappingName.find_first_of(": "));
    const NcVariable* mapping = mappingName.empty() ? nullptr : file.findVariable(mappingName);
    if (mapping == nullptr) return {};
    GridMapping result;
    result.name = file.text(mapping->id, "grid_mapping_name");
    if (result.name.empty()) return {};
    // A projection has a handful of parameters of one or two values each; anything longer is
    // not one of them and is not read.
    constexpr std::size_t kMostValues = 4;
    for (const std::string& key : file.attributeNames(mapping->id)) {
        std::vector<double> values = file.numericAttribute(mapping->id, key.c_str());
        if (!values.empty() && values.size() <= kMostValues) {
            result.parameters.emplace_back(key, std::move(values));
        }
    }
    return result;
}

bool isLengthUnit(const std::string& units) { return metresPer(units) > 0.0; }

}  // namespace ensil::data

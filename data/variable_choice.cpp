#include "data/variable_choice.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <tuple>

#include "data/ascii_case.h"

namespace ensil::data {
namespace {

bool oneOf(const std::string& word, std::initializer_list<const char*> words) {
    return std::any_of(words.begin(), words.end(), [&word](const char* w) { return word == w; });
}

bool contains(const std::string& text, const char* part) {
    return text.find(part) != std::string::npos;
}

bool staggered(const VariableInfo& v) {
    return std::any_of(v.dimensions.begin(), v.dimensions.end(),
                       [](const std::string& d) { return asciiLower(d).ends_with("_stag"); });
}

}  // namespace

Quantity quantityOf(const std::string& nameIn, const std::string& standardNameIn,
                    const std::string& longNameIn) {
    const std::string name = asciiLower(nameIn);
    const std::string standard = asciiLower(standardNameIn);
    const std::string longName = asciiLower(longNameIn);
    // A perturbation from a base state (WRF's T, P, PH) is not the quantity a figure shows.
    if (contains(longName, "perturbation")) return Quantity::Other;
    // Names as ECMWF (cfgrib's short names), NCEP, CMIP, WRF and the CF standard names give them.
    if (oneOf(name, {"wind_speed", "ws", "wspd", "ff", "wind", "windspeed"}) ||
        standard == "wind_speed" || contains(longName, "wind speed")) {
        return Quantity::WindSpeed;
    }
    if (oneOf(name, {"w", "wa", "omega", "wap", "vvel", "dzdt"}) ||
        oneOf(standard, {"upward_air_velocity", "lagrangian_tendency_of_air_pressure"}) ||
        contains(longName, "vertical velocity")) {
        return Quantity::VerticalVelocity;
    }
    if (oneOf(name, {"u", "v", "ua", "va", "uwnd", "vwnd", "x_wind", "y_wind", "ugrd", "vgrd"}) ||
        oneOf(standard, {"eastward_wind", "northward_wind", "x_wind", "y_wind",
                         "grid_eastward_wind", "grid_northward_wind"}) ||
        contains(longName, "component of wind") || contains(longName, "wind component")) {
        return Quantity::WindComponent;
    }
    if (oneOf(name, {"theta", "pt", "th", "pot_temp", "air_potential_temperature"}) ||
        standard == "air_potential_temperature" || contains(longName, "potential temperature")) {
        return Quantity::PotentialTemperature;
    }
    if (oneOf(name, {"t", "ta", "tk", "temp", "temperature", "air_temperature", "tmp"}) ||
        standard == "air_temperature" || longName == "temperature" ||
        contains(longName, "air temperature")) {
        return Quantity::Temperature;
    }
    if (oneOf(name, {"z", "gh", "zg", "hgt", "geopotential", "geopotential_height", "phi"}) ||
        oneOf(standard, {"geopotential", "geopotential_height"}) ||
        contains(longName, "geopotential")) {
        return Quantity::GeopotentialHeight;
    }
    if (oneOf(name, {"q", "r", "rh", "qv", "hus", "hur", "qvapor", "shum", "rhum", "spfh"}) ||
        contains(standard, "humidity") || contains(longName, "humidity") ||
        contains(longName, "water vapor mixing ratio")) {
        return Quantity::Humidity;
    }
    return Quantity::Other;
}

std::optional<std::size_t> chooseVariable(const std::vector<VariableInfo>& variables) {
    std::optional<std::size_t> chosen;
    // Smaller is better: a sheet after a volume, a staggered field after the rest, the quantity's
    // rank, then more levels first.
    using Key = std::tuple<bool, bool, int, long long>;
    Key best{};
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableInfo& v = variables[i];
        if (!v.usable) continue;
        const Quantity q = v.derived && v.name == "wind_speed"
                               ? Quantity::WindSpeed
                               : quantityOf(v.name, v.standardName, v.longName);
        const Key key{v.levels < 3, staggered(v), static_cast<int>(q),
                      -static_cast<long long>(v.levels)};
        if (!chosen || key < best) {
            chosen = i;
            best = key;
        }
    }
    return chosen;
}

}  // namespace ensil::data

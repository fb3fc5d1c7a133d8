// The variable a file opens with when none is named (METHODS.md "The variable data open with"):
// the physical quantity a meteorologist would look at first, from a ranked list (wind speed,
// temperature, potential temperature, geopotential height, humidity, any other field, a wind
// component, vertical velocity), a field on staggered levels (WRF's *_stag) after every other,
// and a field with three or more levels before a two-level sheet. The NetCDF and GRIB readers
// share it. Pure; any thread.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "data/ensemble_reader.h"

namespace ensil::data {

// What a variable is, as far as choosing goes; ordered as ranked (the first is chosen first).
enum class Quantity {
    WindSpeed,
    Temperature,
    PotentialTemperature,
    GeopotentialHeight,
    Humidity,
    Other,
    WindComponent,
    VerticalVelocity,
};

// From its name, CF standard name and long name (case does not matter).
Quantity quantityOf(const std::string& name, const std::string& standardName,
                    const std::string& longName);

// The index in `variables` of the one to open: usable, ranked as above, then the one with the
// most levels, then the first in the file. None when none is usable.
std::optional<std::size_t> chooseVariable(const std::vector<VariableInfo>& variables);

}  // namespace ensil::data

// The levels a data selection keeps (DataSelection::levels): "1000:100 hPa" keeps the vertical
// levels from 1000 to 100 hPa, ends included, so that the box holds the troposphere rather than
// a stratosphere that squashes the weather into its floor. The range is given in any units
// UDUNITS-2 can convert to the vertical axis's (hPa, Pa, millibars, km, m), or without units
// in the axis's own. Applied where every reader is called (data/ensemble_reader.cpp), so the
// command line, the workbench, projects, Python and MPI all read the same levels.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "data/grid.h"

namespace ensil::data {

struct LevelRange {
    double from = 0.0;
    double to = 0.0;
    std::string units;  // empty: the vertical axis's own

    bool operator==(const LevelRange&) const = default;
};

// "1000:100hPa", "1000:100 hPa", "0:12 km", "3:20" (the axis's own units). Throws
// Error(InvalidArgument) saying what is wrong and showing the form.
LevelRange parseLevelRange(const std::string& text);
// "1000:100 hPa": parseLevelRange's form, read back as it was given.
std::string levelRangeText(const LevelRange& range);

// The layers [first, first + count) of `z` whose coordinates lie within the range (ends
// included). Throws Error(InvalidArgument), naming `source` and the axis with its range, when
// the range's units cannot be converted to the axis's or fewer than 2 levels lie within it.
struct LayerSpan {
    std::size_t first = 0;
    std::size_t count = 0;
};
LayerSpan layersWithin(const Axis& z, const LevelRange& range, const std::string& source);

}  // namespace ensil::data

// How much the box stretches heights against distances (METHODS.md section 3, "The vertical
// scale the figure states"): the drawn height over the drawn width, divided by the true height
// over the true width. An atmosphere in hPa over a map in degrees is drawn 0.2 units high, which
// on a continent-sized map is hundreds of times its true height; the figure says by how much.
// Pure; any thread.
#pragma once

#include <optional>

#include "data/display_frame.h"
#include "data/grid.h"

namespace ensil::data {

struct VerticalScale {
    double factor = 1.0;              // drawn heights are this many times their true proportion
    bool standardAtmosphere = false;  // pressure levels placed at the standard atmosphere's heights
};

// None when a true proportion cannot be known: a vertical axis that is neither a pressure nor a
// length (model level numbers), horizontal axes that are neither both degrees nor both lengths.
std::optional<VerticalScale> verticalScaleOf(const Grid& grid, const DisplayFrame& frame);

// The height in metres of a pressure in hPa in the ICAO standard atmosphere (ISO 2533): the
// troposphere's lapse rate of 6.5 K/km to 11 km, isothermal to 20 km, 1 K/km above.
double standardAtmosphereHeight(double hectopascals);

}  // namespace ensil::data

// Tick values for axis labels: round numbers (1, 2, 2.5 or 5 times a power of ten) covering a
// range, as a person would label a chart. Pure; any thread.
#pragma once

#include <string>
#include <vector>

#include "data/grid.h"

namespace ensil::gl {

// Ticks inside [lo, hi] (either order), at most about `wanted` + 2 of them, ascending.
// A degenerate or non-finite range gives no ticks.
std::vector<double> niceTicks(double lo, double hi, int wanted = 5);

// How an axis is labelled as scientists read it: pressure in hPa whatever the file's unit, at
// the standard levels inside the range (1000, 850, 700, 500, 300, 200, 100, ...; the main ones
// first, so where labels collide the main ones stay); heights above 10 km in km; anything else
// in its own units at round numbers.
struct AxisLabelling {
    std::vector<double> ticks;  // in the axis's own units, in order of importance
    double shownPerUnit = 1.0;  // a tick's label is tick * shownPerUnit
    std::string units;          // the units the labels are in
};
AxisLabelling labellingFor(const data::Axis& axis);

}  // namespace ensil::gl

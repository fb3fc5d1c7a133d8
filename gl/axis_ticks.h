// Tick values for axis labels: round numbers (1, 2, 2.5 or 5 times a power of ten) covering a
// range, as a person would label a chart. Pure; any thread.
#pragma once

#include <vector>

namespace ensil::gl {

// Ticks inside [lo, hi] (either order), at most about `wanted` + 2 of them, ascending.
// A degenerate or non-finite range gives no ticks.
std::vector<double> niceTicks(double lo, double hi, int wanted = 5);

}  // namespace ensil::gl

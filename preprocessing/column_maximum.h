// The maximum of a member over the vertical axis at every horizontal point: a 2D map of where
// the strongest values are (for wind speed, where the jet cores run). Drawn on the floor of the
// 3D view for orientation. NaN where the whole column is missing. Pure function; any thread.
#pragma once

#include <vector>

#include "data/ensemble.h"

namespace ensil::prep {

// Returns nx * ny values, x fastest.
std::vector<float> computeColumnMaximum(const data::Grid& grid, const data::Member& member);

}  // namespace ensil::prep

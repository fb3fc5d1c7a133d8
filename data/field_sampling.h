// A field's value between grid points: trilinear interpolation at a fractional grid index,
// leaving out missing (NaN) corners, so a value under the cursor is what the data say there.
// Pure; any thread.
#pragma once

#include <glm/vec3.hpp>
#include <span>

#include "data/grid.h"

namespace ensil::data {

// NaN when every corner is missing or `values` is not one value per grid point.
float sampleTrilinear(const Grid& grid, std::span<const float> values, const glm::dvec3& index);

}  // namespace ensil::data

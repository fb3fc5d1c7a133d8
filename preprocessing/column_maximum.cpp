#include "preprocessing/column_maximum.h"

#include <cmath>
#include <limits>

namespace ensil::prep {

std::vector<float> computeColumnMaximum(const data::Grid& grid, const data::Member& member) {
    const std::size_t nxy = grid.nx() * grid.ny();
    std::vector<float> result(nxy, std::numeric_limits<float>::quiet_NaN());
    for (std::size_t k = 0; k < grid.nz(); ++k) {
        const float* slab = member.values.data() + k * nxy;
        for (std::size_t p = 0; p < nxy; ++p) {
            // NaN compares false, so a missing value never wins, and a missing maximum so far
            // (r != r) always loses. A select, not a skip, so the loop vectorises.
            const float v = slab[p], r = result[p];
            result[p] = (v > r || r != r) ? v : r;
        }
    }
    return result;
}

}  // namespace ensil::prep

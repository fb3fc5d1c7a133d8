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
            // NaN compares false, so a missing value never wins and never blocks a valid one.
            if (!std::isnan(slab[p]) && !(slab[p] <= result[p])) result[p] = slab[p];
        }
    }
    return result;
}

}  // namespace ensil::prep

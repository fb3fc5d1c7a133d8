#include "preprocessing/exceedance.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "preprocessing/point_blocks.h"
#include "preprocessing/similarity.h"

namespace ensil::prep {

data::FieldValues computeExceedance(const data::Ensemble& ensemble, float isovalue,
                                    const std::stop_token& stop) {
    checkDistanceArguments(ensemble, isovalue, "compute the exceedance probability");
    const std::size_t points = ensemble.grid.pointCount();
    data::FieldValues exceedance(points);
    forEachPointBlock(points, stop, {}, 0.0, 1.0, [&](std::size_t first, std::size_t count) {
        std::vector<std::uint32_t> valid(count, 0), above(count, 0);
        for (const data::Member& member : ensemble.members) {
            const float* f = member.values.data() + first;
            // NaN and the infinities fail the first comparison; NaN fails the second too. The
            // comparisons combined bit by bit (no short circuit), so the loop vectorises.
            for (std::size_t p = 0; p < count; ++p) {
                const auto finite =
                    static_cast<std::uint32_t>(std::abs(f[p]) <= std::numeric_limits<float>::max());
                valid[p] += finite;
                above[p] += finite & static_cast<std::uint32_t>(f[p] > isovalue);
            }
        }
        for (std::size_t p = 0; p < count; ++p) {
            // As EnsembleStatisticsAccumulator::result divides, so the values are the same.
            exceedance[first + p] =
                valid[p] == 0 ? std::numeric_limits<float>::quiet_NaN()
                              : static_cast<float>(static_cast<double>(above[p]) / valid[p]);
        }
    });
    return exceedance;
}

}  // namespace ensil::prep

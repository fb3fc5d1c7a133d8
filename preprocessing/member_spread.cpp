#include "preprocessing/member_spread.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "preprocessing/point_blocks.h"
#include "preprocessing/similarity.h"

namespace ensil::prep {

data::FieldValues computeMemberSpread(const data::Ensemble& ensemble, const std::stop_token& stop) {
    // Any finite isovalue: the spread has none, and the checks are those of every statistic.
    checkDistanceArguments(ensemble, 0.0F, "compute the members' spread");
    const std::size_t points = ensemble.grid.pointCount();
    data::FieldValues spread(points);
    forEachPointBlock(points, stop, {}, 0.0, 1.0, [&](std::size_t first, std::size_t count) {
        std::vector<float> shift(count);
        // The count in double too: one vector width through the loop, which GCC needs to
        // vectorise the selects (counts stay exact in double).
        std::vector<double> sum(count, 0.0), squares(count, 0.0), valid(count, 0.0);
        const float* reference = ensemble.members.front().values.data() + first;
        for (std::size_t p = 0; p < count; ++p) {
            shift[p] =
                std::abs(reference[p]) <= std::numeric_limits<float>::max() ? reference[p] : 0.0F;
        }
        // Branch-free (selects, not skips), so each member's pass vectorises. NaN and the
        // infinities fail the comparison (the shift is finite).
        for (const data::Member& member : ensemble.members) {
            const float* f = member.values.data() + first;
            for (std::size_t p = 0; p < count; ++p) {
                const double x = static_cast<double>(f[p]) - static_cast<double>(shift[p]);
                const bool ok = std::abs(x) <= std::numeric_limits<double>::max();
                const double d = ok ? x : 0.0;
                sum[p] += d;
                squares[p] += d * d;
                valid[p] += ok ? 1.0 : 0.0;
            }
        }
        for (std::size_t p = 0; p < count; ++p) {
            const double n = valid[p];
            // The difference is >= 0 in exact arithmetic; the clamp only guards rounding.
            spread[first + p] =
                n < 2.0 ? std::numeric_limits<float>::quiet_NaN()
                        : static_cast<float>(std::sqrt(
                              std::max(0.0, squares[p] - sum[p] * sum[p] / n) / (n - 1.0)));
        }
    });
    return spread;
}

}  // namespace ensil::prep

#include "preprocessing/mean_member.h"

#include <cmath>
#include <limits>
#include <vector>

#include "data/error.h"
#include "preprocessing/point_blocks.h"

namespace ensil::prep {

data::Member computeMeanMember(const data::Ensemble& ensemble, const std::stop_token& stop,
                               const data::Progress& progress) {
    if (ensemble.members.empty()) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "cannot compute the mean member of an ensemble with no members");
    }
    const std::size_t n = ensemble.grid.pointCount();
    const std::size_t members = ensemble.memberCount();
    data::Member mean;
    mean.name = "mean";
    mean.values.resize(n);
    forEachPointBlock(n, stop, progress, 0.0, 1.0, [&](std::size_t first, std::size_t count) {
        // Selects rather than skips, and the count in double (one vector width through the
        // loop), so that each member's pass vectorises; counts stay exact in double.
        std::vector<double> sum(count, 0.0), valid(count, 0.0);
        for (std::size_t m = 0; m < members; ++m) {
            const float* values = ensemble.members[m].values.data() + first;
            for (std::size_t p = 0; p < count; ++p) {
                const bool present = values[p] == values[p];  // NaN is missing
                sum[p] += present ? static_cast<double>(values[p]) : 0.0;
                valid[p] += present ? 1.0 : 0.0;
            }
        }
        for (std::size_t p = 0; p < count; ++p) {
            mean.values[first + p] = valid[p] > 0.0 ? static_cast<float>(sum[p] / valid[p])
                                                    : std::numeric_limits<float>::quiet_NaN();
        }
    });
    return mean;
}

}  // namespace ensil::prep

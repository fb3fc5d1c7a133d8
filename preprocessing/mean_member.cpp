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
        std::vector<double> sum(count, 0.0);
        std::vector<std::uint32_t> valid(count, 0);
        for (std::size_t m = 0; m < members; ++m) {
            const float* values = ensemble.members[m].values.data() + first;
            for (std::size_t p = 0; p < count; ++p) {
                if (!std::isnan(values[p])) {
                    sum[p] += values[p];
                    ++valid[p];
                }
            }
        }
        for (std::size_t p = 0; p < count; ++p) {
            mean.values[first + p] = valid[p] > 0 ? static_cast<float>(sum[p] / valid[p])
                                                  : std::numeric_limits<float>::quiet_NaN();
        }
    });
    return mean;
}

}  // namespace ensil::prep

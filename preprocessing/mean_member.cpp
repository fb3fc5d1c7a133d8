#include "preprocessing/mean_member.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "data/error.h"

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
    // Blocks of points on threads of their own; each point's members summed in member order,
    // so the mean does not depend on the threads.
    const std::size_t blocks = (n + kPointsPerBlock - 1) / kPointsPerBlock;
    data::PartsProgress blocksDone(progress, blocks);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        data::throwIfStopped(stop);
        const std::size_t first = b * kPointsPerBlock;
        const std::size_t count = std::min(kPointsPerBlock, n - first);
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
        blocksDone.partDone();
    });
    return mean;
}

}  // namespace ensil::prep

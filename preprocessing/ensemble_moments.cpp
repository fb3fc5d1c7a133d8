#include "preprocessing/ensemble_moments.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "preprocessing/mean_member.h"

namespace ensil::prep {

EnsembleMoments computeEnsembleMoments(const data::Ensemble& ensemble, const std::stop_token& stop,
                                       const data::Progress& progress) {
    EnsembleMoments moments;
    moments.mean =
        computeMeanMember(ensemble, stop, [&](double f) { data::report(progress, 0.5 * f); });
    const std::size_t n = ensemble.grid.pointCount();
    const std::size_t members = ensemble.memberCount();
    const float* mean = moments.mean.values.data();
    moments.variance.resize(n);
    // As the mean: blocks of points on threads of their own, members in order within each.
    const std::size_t blocks = (n + kPointsPerBlock - 1) / kPointsPerBlock;
    data::PartsProgress blocksDone(progress, blocks, 0.5, 1.0);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        data::throwIfStopped(stop);
        const std::size_t first = b * kPointsPerBlock;
        const std::size_t count = std::min(kPointsPerBlock, n - first);
        std::vector<double> sum(count, 0.0);
        std::vector<std::uint32_t> valid(count, 0);
        for (std::size_t m = 0; m < members; ++m) {
            const float* f = ensemble.members[m].values.data() + first;
            for (std::size_t p = 0; p < count; ++p) {
                if (!std::isnan(f[p])) {
                    const double d = static_cast<double>(f[p]) - mean[first + p];
                    sum[p] += d * d;
                    ++valid[p];
                }
            }
        }
        for (std::size_t p = 0; p < count; ++p) {
            moments.variance[first + p] = valid[p] > 0 ? static_cast<float>(sum[p] / valid[p])
                                                       : std::numeric_limits<float>::quiet_NaN();
        }
        blocksDone.partDone();
    });
    return moments;
}

}  // namespace ensil::prep

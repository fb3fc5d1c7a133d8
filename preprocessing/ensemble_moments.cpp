#include "preprocessing/ensemble_moments.h"

#include <cmath>
#include <limits>

#include "preprocessing/mean_member.h"
#include "preprocessing/point_blocks.h"

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
    forEachPointBlock(n, stop, progress, 0.5, 1.0, [&](std::size_t first, std::size_t count) {
        // Selects rather than skips, and the count in double, so that each member's pass
        // vectorises (as in the mean member).
        std::vector<double> sum(count, 0.0), valid(count, 0.0);
        const float* blockMean = mean + first;
        for (std::size_t m = 0; m < members; ++m) {
            const float* f = ensemble.members[m].values.data() + first;
            for (std::size_t p = 0; p < count; ++p) {
                // A missing value (NaN) makes the difference NaN, which fails the comparison;
                // so does an infinite one, which has made the mean infinite too (the variance
                // there is NaN either way). Tested on the difference, the select vectorises.
                const double x = static_cast<double>(f[p]) - static_cast<double>(blockMean[p]);
                const bool present = std::abs(x) <= std::numeric_limits<double>::max();
                const double d = present ? x : 0.0;
                sum[p] += d * d;
                valid[p] += present ? 1.0 : 0.0;
            }
        }
        for (std::size_t p = 0; p < count; ++p) {
            moments.variance[first + p] = valid[p] > 0.0 ? static_cast<float>(sum[p] / valid[p])
                                                         : std::numeric_limits<float>::quiet_NaN();
        }
    });
    return moments;
}

}  // namespace ensil::prep

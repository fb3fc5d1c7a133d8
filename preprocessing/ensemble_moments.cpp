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
    });
    return moments;
}

}  // namespace ensil::prep

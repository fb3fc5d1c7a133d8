#include "preprocessing/ensemble_moments.h"

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
    std::vector<double> sum(n, 0.0);
    std::vector<std::uint32_t> count(n, 0);
    const float* mean = moments.mean.values.data();
    for (std::size_t m = 0; m < ensemble.memberCount(); ++m) {
        data::throwIfStopped(stop);
        const float* f = ensemble.members[m].values.data();
        for (std::size_t p = 0; p < n; ++p) {
            if (!std::isnan(f[p])) {
                const double d = static_cast<double>(f[p]) - mean[p];
                sum[p] += d * d;
                ++count[p];
            }
        }
        data::report(progress, 0.5 + 0.5 * static_cast<double>(m + 1) /
                                         static_cast<double>(ensemble.memberCount()));
    }
    moments.variance.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
        moments.variance[p] = count[p] > 0 ? static_cast<float>(sum[p] / count[p])
                                           : std::numeric_limits<float>::quiet_NaN();
    }
    return moments;
}

}  // namespace ensil::prep

#include "preprocessing/mean_member.h"

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
    std::vector<double> sum(n, 0.0);
    std::vector<std::uint32_t> count(n, 0);
    const std::size_t members = ensemble.memberCount();
    for (std::size_t m = 0; m < members; ++m) {
        data::throwIfStopped(stop);
        const float* values = ensemble.members[m].values.data();
        for (std::size_t p = 0; p < n; ++p) {
            if (!std::isnan(values[p])) {
                sum[p] += values[p];
                ++count[p];
            }
        }
        data::report(progress, static_cast<double>(m + 1) / static_cast<double>(members));
    }
    data::Member mean;
    mean.name = "mean";
    mean.values.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
        mean.values[p] = count[p] > 0 ? static_cast<float>(sum[p] / count[p])
                                      : std::numeric_limits<float>::quiet_NaN();
    }
    return mean;
}

}  // namespace ensil::prep

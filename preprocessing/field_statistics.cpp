#include "preprocessing/field_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace ensil::prep {

FieldStatistics computeFieldStatistics(const data::Ensemble& ensemble, std::size_t bins,
                                       const std::stop_token& stop,
                                       const data::Progress& progress) {
    FieldStatistics stats;
    float lo = std::numeric_limits<float>::infinity();
    float hi = -lo;
    double sum = 0.0;
    const std::size_t members = ensemble.memberCount();
    // Two passes over the members: the range first, then the histogram over that range.
    for (std::size_t m = 0; m < members; ++m) {
        data::throwIfStopped(stop);
        for (const float v : ensemble.members[m].values) {
            if (std::isnan(v)) {
                ++stats.missingCount;
                continue;
            }
            lo = std::min(lo, v);
            hi = std::max(hi, v);
            sum += v;
            ++stats.validCount;
        }
        data::report(progress, 0.5 * static_cast<double>(m + 1) / static_cast<double>(members));
    }
    stats.histogram.assign(bins, 0);
    if (stats.validCount == 0) {
        data::report(progress, 1.0);
        return stats;
    }
    stats.minimum = lo;
    stats.maximum = hi;
    stats.mean = sum / static_cast<double>(stats.validCount);
    if (bins > 0) {
        const double width = static_cast<double>(hi) - static_cast<double>(lo);
        const double scale = width > 0.0 ? static_cast<double>(bins) / width : 0.0;
        for (std::size_t m = 0; m < members; ++m) {
            data::throwIfStopped(stop);
            for (const float v : ensemble.members[m].values) {
                if (std::isnan(v)) continue;
                const auto bin = static_cast<std::size_t>((static_cast<double>(v) - lo) * scale);
                ++stats.histogram[std::min(bin, bins - 1)];
            }
            data::report(progress,
                         0.5 + 0.5 * static_cast<double>(m + 1) / static_cast<double>(members));
        }
    }
    return stats;
}

}  // namespace ensil::prep

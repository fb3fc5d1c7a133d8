#include "preprocessing/field_statistics.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace ensil::prep {
namespace {

// One member's share of the statistics, made on a thread of its own.
struct MemberShare {
    float lo = std::numeric_limits<float>::infinity();
    float hi = -std::numeric_limits<float>::infinity();
    double sum = 0.0;
    std::size_t valid = 0, missing = 0;
};

}  // namespace

FieldStatistics computeFieldStatistics(const data::Ensemble& ensemble, std::size_t bins,
                                       const std::stop_token& stop,
                                       const data::Progress& progress) {
    FieldStatistics stats;
    const std::size_t members = ensemble.memberCount();
    // Two passes over the members, each member on a thread of its own: the range first, then
    // the histogram over that range. The members' shares are added in member order, so the
    // figures do not depend on the threads.
    std::vector<MemberShare> shares(members);
    data::PartsProgress rangesDone(progress, members, 0.0, 0.5);
    tbb::parallel_for(std::size_t{0}, members, [&](std::size_t m) {
        data::throwIfStopped(stop);
        MemberShare& s = shares[m];
        for (const float v : ensemble.members[m].values) {
            if (std::isnan(v)) {
                ++s.missing;
                continue;
            }
            s.lo = std::min(s.lo, v);
            s.hi = std::max(s.hi, v);
            s.sum += v;
            ++s.valid;
        }
        rangesDone.partDone();
    });
    float lo = std::numeric_limits<float>::infinity();
    float hi = -lo;
    double sum = 0.0;
    for (const MemberShare& s : shares) {
        lo = std::min(lo, s.lo);
        hi = std::max(hi, s.hi);
        sum += s.sum;
        stats.validCount += s.valid;
        stats.missingCount += s.missing;
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
        std::vector<std::vector<std::uint64_t>> counts(members);
        data::PartsProgress binsDone(progress, members, 0.5, 1.0);
        tbb::parallel_for(std::size_t{0}, members, [&](std::size_t m) {
            data::throwIfStopped(stop);
            std::vector<std::uint64_t>& histogram = counts[m];
            histogram.assign(bins, 0);
            for (const float v : ensemble.members[m].values) {
                if (std::isnan(v)) continue;
                const auto bin = static_cast<std::size_t>((static_cast<double>(v) - lo) * scale);
                ++histogram[std::min(bin, bins - 1)];
            }
            binsDone.partDone();
        });
        for (const std::vector<std::uint64_t>& histogram : counts) {
            for (std::size_t b = 0; b < bins; ++b) stats.histogram[b] += histogram[b];
        }
    }
    return stats;
}

}  // namespace ensil::prep

#include "preprocessing/field_statistics.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>

#include "preprocessing/lanes.h"

namespace ensil::prep {
namespace {

// One member's share of the statistics, made on a thread of its own.
struct MemberShare {
    float lo = std::numeric_limits<float>::infinity();
    float hi = -std::numeric_limits<float>::infinity();
    double sum = 0.0;
    std::size_t valid = 0, missing = 0;
};

MemberShare shareOf(std::span<const float> values) {
    std::array<MemberShare, kLanes> lanes;
    forEachInLanes(values.size(), [&](std::size_t lane, std::size_t i) {
        MemberShare& s = lanes[lane];
        const float v = values[i];
        if (std::isnan(v)) {
            ++s.missing;
            return;
        }
        s.lo = std::min(s.lo, v);
        s.hi = std::max(s.hi, v);
        s.sum += v;
        ++s.valid;
    });
    MemberShare share;
    for (const MemberShare& lane : lanes) {
        share.lo = std::min(share.lo, lane.lo);
        share.hi = std::max(share.hi, lane.hi);
        share.sum += lane.sum;
        share.valid += lane.valid;
        share.missing += lane.missing;
    }
    return share;
}

std::vector<std::uint64_t> histogramOf(std::span<const float> values, float lo, double scale,
                                       std::size_t bins) {
    std::vector<std::uint64_t> lanes(kLanes * bins, 0);
    forEachInLanes(values.size(), [&](std::size_t lane, std::size_t i) {
        if (std::isnan(values[i])) return;
        const auto bin = static_cast<std::size_t>((static_cast<double>(values[i]) - lo) * scale);
        ++lanes[lane * bins + std::min(bin, bins - 1)];
    });
    std::vector<std::uint64_t> histogram(bins, 0);
    for (std::size_t lane = 0; lane < kLanes; ++lane) {
        for (std::size_t b = 0; b < bins; ++b) histogram[b] += lanes[lane * bins + b];
    }
    return histogram;
}

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
        shares[m] = shareOf(ensemble.members[m].values);
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
            counts[m] = histogramOf(ensemble.members[m].values, lo, scale, bins);
            binsDone.partDone();
        });
        for (const std::vector<std::uint64_t>& histogram : counts) {
            for (std::size_t b = 0; b < bins; ++b) stats.histogram[b] += histogram[b];
        }
    }
    return stats;
}

}  // namespace ensil::prep

#include "preprocessing/member_median.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "preprocessing/point_blocks.h"
#include "preprocessing/similarity.h"

namespace ensil::prep {

namespace {
// Points whose medians are found together: each member's run of them is read in one go, and
// their keys (this many times the member count, 4 bytes each) stay in cache while the search
// passes over them.
constexpr std::size_t kPointsPerGather = 256;

// Floats as integers in the same order (a negative float's other bits count down), so that a
// value's rank is found by a binary search over integers, compared in every point at once.
// A point-by-point selection (std::nth_element) mispredicted most of its comparisons and took
// five times as long on the demo.
std::int32_t orderKey(float value) {
    const auto bits = std::bit_cast<std::int32_t>(value);
    return bits ^ ((bits >> 31) & 0x7FFFFFFF);
}
float fromOrderKey(std::int32_t key) {
    return std::bit_cast<float>(key ^ ((key >> 31) & 0x7FFFFFFF));
}
const std::int32_t kLowestKey = orderKey(-std::numeric_limits<float>::max());
const std::int32_t kHighestKey = orderKey(std::numeric_limits<float>::max());
// A missing value: above every finite one's key, so never counted at or below one.
constexpr std::int32_t kMissingKey = std::numeric_limits<std::int32_t>::max();

// The medians of `count` points whose members' keys are keys[m * kPointsPerGather + p].
// Branchless loops over the points, which GCC vectorises.
void mediansOfGather(const std::int32_t* keys, std::size_t members, std::size_t count,
                     float* median) {
    std::int32_t lo[kPointsPerGather], hi[kPointsPerGather], mid[kPointsPerGather];
    std::int32_t valid[kPointsPerGather], atOrBelow[kPointsPerGather];
    std::fill(valid, valid + count, 0);
    for (std::size_t m = 0; m < members; ++m) {
        const std::int32_t* k = keys + m * kPointsPerGather;
        for (std::size_t p = 0; p < count; ++p) valid[p] += k[p] != kMissingKey ? 1 : 0;
    }
    // The upper middle value (index n / 2 of the n sorted ones) is the smallest key with more
    // than n / 2 keys at or below it: a binary search over the keys' range, 32 halvings. (Each
    // point's own lowest and highest keys as the range, with an end when every search has
    // ended, made it slower on the demo: wind speeds near zero span many exponents.)
    std::fill(lo, lo + count, kLowestKey);
    std::fill(hi, hi + count, kHighestKey);
    for (int halving = 0; halving < 32; ++halving) {
        for (std::size_t p = 0; p < count; ++p) {
            const auto width =
                static_cast<std::uint32_t>(hi[p]) - static_cast<std::uint32_t>(lo[p]);
            mid[p] = static_cast<std::int32_t>(static_cast<std::uint32_t>(lo[p]) + width / 2);
            atOrBelow[p] = 0;
        }
        for (std::size_t m = 0; m < members; ++m) {
            const std::int32_t* k = keys + m * kPointsPerGather;
            for (std::size_t p = 0; p < count; ++p) atOrBelow[p] += k[p] <= mid[p] ? 1 : 0;
        }
        for (std::size_t p = 0; p < count; ++p) {
            const bool enough = atOrBelow[p] > valid[p] / 2;
            hi[p] = enough ? mid[p] : hi[p];
            // Unsigned: a point without values (never enough) runs past the range, harmlessly
            // (its median is NaN), and must not overflow.
            lo[p] =
                enough ? lo[p] : static_cast<std::int32_t>(static_cast<std::uint32_t>(mid[p]) + 1U);
        }
    }
    // The lower middle value (index n / 2 - 1), for an even n: the largest key below the upper
    // one when n / 2 keys or more are below it, else the upper one itself (the two are equal).
    std::int32_t* below = mid;  // reused: the count of keys below the upper middle one
    std::int32_t* largestBelow = atOrBelow;
    for (std::size_t p = 0; p < count; ++p) {
        below[p] = 0;
        largestBelow[p] = std::numeric_limits<std::int32_t>::min();
    }
    for (std::size_t m = 0; m < members; ++m) {
        const std::int32_t* k = keys + m * kPointsPerGather;
        for (std::size_t p = 0; p < count; ++p) {
            const bool less = k[p] < lo[p];
            below[p] += less ? 1 : 0;
            largestBelow[p] = less ? std::max(largestBelow[p], k[p]) : largestBelow[p];
        }
    }
    for (std::size_t p = 0; p < count; ++p) {
        const float upper = fromOrderKey(lo[p]);
        const std::int32_t n = valid[p];
        const float lower = fromOrderKey(below[p] >= n / 2 ? largestBelow[p] : lo[p]);
        median[p] = n == 0       ? std::numeric_limits<float>::quiet_NaN()
                    : n % 2 == 1 ? upper
                                 : 0.5F * lower + 0.5F * upper;  // no overflow near the range
    }
}
}  // namespace

data::FieldValues computeMemberMedian(const data::Ensemble& ensemble, const std::stop_token& stop) {
    checkDistanceArguments(ensemble, 0.0F, "take the members' median");  // the value counts
    const std::size_t members = ensemble.memberCount();
    const std::size_t points = ensemble.grid.pointCount();
    data::FieldValues median(points);
    forEachPointBlock(points, stop, {}, 0.0, 1.0, [&](std::size_t first, std::size_t count) {
        std::vector<std::int32_t> keys(kPointsPerGather * members);
        for (std::size_t start = first; start < first + count; start += kPointsPerGather) {
            const std::size_t n = std::min(kPointsPerGather, first + count - start);
            for (std::size_t m = 0; m < members; ++m) {
                const float* f = ensemble.members[m].values.data() + start;
                std::int32_t* k = keys.data() + m * kPointsPerGather;
                for (std::size_t p = 0; p < n; ++p) {
                    k[p] = std::isfinite(f[p]) ? orderKey(f[p]) : kMissingKey;
                }
            }
            mediansOfGather(keys.data(), members, n, median.data() + start);
        }
    });
    return median;
}

}  // namespace ensil::prep

#include "preprocessing/band_envelope.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "data/error.h"
#include "preprocessing/point_blocks.h"
#include "preprocessing/similarity.h"

namespace ensil::prep {

BandEnvelope computeBandEnvelope(const data::Ensemble& ensemble,
                                 std::span<const std::size_t> members,
                                 const std::stop_token& stop) {
    checkDistanceArguments(ensemble, 0.0F, "make the band's envelope");  // the value counts
    if (members.empty()) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "the band's envelope needs at least one member");
    }
    const std::size_t points = ensemble.grid.pointCount();
    for (const std::size_t m : members) {
        if (m >= ensemble.memberCount()) {
            throw data::Error(data::ErrorKind::InvalidArgument,
                              "member index " + std::to_string(m) + " is out of range: the " +
                                  "ensemble has " + std::to_string(ensemble.memberCount()) +
                                  " members");
        }
    }
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    constexpr float kLargest = std::numeric_limits<float>::max();
    BandEnvelope out;
    out.lowest.resize(points);
    out.highest.resize(points);
    forEachPointBlock(points, stop, {}, 0.0, 1.0, [&](std::size_t first, std::size_t count) {
        float* lowest = out.lowest.data() + first;
        float* highest = out.highest.data() + first;
        std::fill(lowest, lowest + count, std::numeric_limits<float>::infinity());
        std::fill(highest, highest + count, -std::numeric_limits<float>::infinity());
        for (const std::size_t m : members) {
            const float* f = ensemble.members[m].values.data() + first;
            for (std::size_t p = 0; p < count; ++p) {
                // NaN and the infinities fail the comparison: a missing value makes the lowest
                // NaN for good (NaN stays NaN under the selects) and leaves the highest alone.
                const bool valid = std::abs(f[p]) <= kLargest;
                lowest[p] = valid ? std::min(lowest[p], f[p]) : kNaN;
                highest[p] = valid ? std::max(highest[p], f[p]) : highest[p];
            }
        }
        for (std::size_t p = 0; p < count; ++p) {
            if (!(highest[p] >= -kLargest)) highest[p] = kNaN;  // no valid value
        }
    });
    return out;
}

}  // namespace ensil::prep

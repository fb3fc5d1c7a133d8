#include "preprocessing/default_isovalue.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ensil::prep {
namespace {

// Enough points for the shares to be stable (a few per cent), few enough to take
// milliseconds on the largest grids.
constexpr std::size_t kSampledPoints = 20000;
constexpr double kNearBest = 0.5;
constexpr int kPaperPercentile = 90;

// The value below which `fraction` of the histogram's count lies (its bin's centre).
float percentile(const std::vector<std::uint64_t>& histogram, float minimum, float maximum,
                 double fraction) {
    const std::uint64_t total =
        std::accumulate(histogram.begin(), histogram.end(), std::uint64_t{0});
    if (total == 0 || histogram.empty()) return 0.5F * (minimum + maximum);
    std::uint64_t running = 0;
    for (std::size_t b = 0; b < histogram.size(); ++b) {
        running += histogram[b];
        if (static_cast<double>(running) >= fraction * static_cast<double>(total)) {
            const double t = (static_cast<double>(b) + 0.5) / static_cast<double>(histogram.size());
            return static_cast<float>(minimum + t * (maximum - minimum));
        }
    }
    return maximum;
}

}  // namespace

std::vector<IsovalueCandidate> isovalueCandidates(const data::Ensemble& e,
                                                  const FieldStatistics& s) {
    std::vector<IsovalueCandidate> candidates;
    for (int p = 50; p <= 95; p += 5) {
        candidates.push_back({p, percentile(s.histogram, s.minimum, s.maximum, p / 100.0)});
    }
    const std::size_t points = e.grid.pointCount();
    const std::size_t members = e.memberCount();
    if (points == 0 || members == 0) return candidates;
    const std::size_t stride = std::max<std::size_t>(1, points / kSampledPoints);
    // The sampled points' values gathered once, point by point (a few MB): the candidates then
    // read them in order instead of each reading every member at every sampled point again.
    std::vector<float> sampledValues;
    sampledValues.reserve((points + stride - 1) / stride * members);
    for (std::size_t i = 0; i < points; i += stride) {
        for (std::size_t m = 0; m < members; ++m) sampledValues.push_back(e.members[m].values[i]);
    }
    for (IsovalueCandidate& c : candidates) {
        std::vector<std::size_t> above(members, 0), below(members, 0);
        double disagreement = 0.0;
        std::size_t sampled = 0;
        for (std::size_t first = 0; first < sampledValues.size(); first += members) {
            const float* at = sampledValues.data() + first;
            std::size_t valid = 0, over = 0;
            // Counted without branches: whether a member is above is a coin toss near the
            // isovalue, and mispredicted branches took most of the time. NaN fails both tests.
            for (std::size_t m = 0; m < members; ++m) {
                const float v = at[m];
                const bool present = v == v;
                const bool up = v >= c.isovalue;
                valid += static_cast<std::size_t>(present);
                over += static_cast<std::size_t>(up);
                above[m] += static_cast<std::size_t>(up);
                below[m] += static_cast<std::size_t>(present && !up);
            }
            if (valid == 0) continue;
            const double share = static_cast<double>(over) / static_cast<double>(valid);
            disagreement += 4.0 * share * (1.0 - share);
            ++sampled;
        }
        std::size_t withSurface = 0;
        for (std::size_t m = 0; m < members; ++m) {
            const auto valid = static_cast<double>(above[m] + below[m]);
            withSurface +=
                static_cast<double>(std::min(above[m], below[m])) >= kLeastShare * valid &&
                        valid > 0.0
                    ? 1
                    : 0;
        }
        c.membersWithSurface = static_cast<double>(withSurface) / static_cast<double>(members);
        c.disagreement = sampled > 0 ? disagreement / static_cast<double>(sampled) : 0.0;
    }
    return candidates;
}

float defaultIsovalue(const data::Ensemble& e, const FieldStatistics& s) {
    if (s.validCount == 0) return 0.5F * (s.minimum + s.maximum);
    const std::vector<IsovalueCandidate> candidates = isovalueCandidates(e, s);
    double best = 0.0;
    for (const IsovalueCandidate& c : candidates) {
        if (c.membersWithSurface >= kMostMembers) best = std::max(best, c.disagreement);
    }
    // Nearest the paper's percentile first, the higher of two equally near.
    const IsovalueCandidate* chosen = nullptr;
    for (const IsovalueCandidate& c : candidates) {
        if (c.membersWithSurface < kMostMembers || c.disagreement < kNearBest * best) continue;
        const auto distance = [](const IsovalueCandidate& x) {
            return 2 * std::abs(x.percentile - kPaperPercentile) -
                   (x.percentile > kPaperPercentile ? 1 : 0);
        };
        if (chosen == nullptr || distance(c) < distance(*chosen)) chosen = &c;
    }
    if (chosen == nullptr || best <= 0.0) return percentile(s.histogram, s.minimum, s.maximum, 0.9);
    return chosen->isovalue;
}

}  // namespace ensil::prep

#include "preprocessing/default_isovalue.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "data/display_frame.h"

namespace ensil::prep {
namespace {

// Enough points for the shares to be stable (a few per cent), few enough to take
// milliseconds on the largest grids.
constexpr std::size_t kSampledPoints = 20000;
constexpr std::size_t kSampledColumns = 2000;
constexpr double kNearBest = 0.5;
constexpr int kPaperPercentile = 90;
// The middle half of the box's height, as fractions of it from the floor.
constexpr double kMiddleLow = 0.25;
constexpr double kMiddleHigh = 0.75;

// Per sampled column and member, the lowest and highest value of the member's profile within the
// middle half of the box's height (linear between levels, as the surfaces are): a surface of c
// crosses the column there exactly when low < c < high. Columns x members pairs; NaN (no value
// there) makes both NaN, which no comparison passes.
struct MiddleRanges {
    std::size_t columns = 0;
    std::vector<float> low;
    std::vector<float> high;
    bool anyMiddle = false;  // the grid has a vertical extent to speak of
};

MiddleRanges middleRanges(const data::Ensemble& e) {
    MiddleRanges r;
    const data::Grid& g = e.grid;
    const std::size_t nz = g.nz();
    const std::size_t plane = g.nx() * g.ny();
    if (nz < 2 || plane == 0) return r;
    const data::DisplayFrame frame(g, 1.0F);
    const std::vector<double> table = frame.axisTable(2);
    const double height = frame.boxMax().z;
    if (!(height > 0.0) || table.size() != nz) return r;
    // Each layer (k, k + 1): the part of it, as t from level k to k + 1, within the middle half.
    struct Span {
        std::size_t k;
        double t0, t1;
    };
    std::vector<Span> spans;
    for (std::size_t k = 0; k + 1 < nz; ++k) {
        const double f0 = table[k] / height;
        const double f1 = table[k + 1] / height;
        if (f0 == f1) continue;
        double t0 = (kMiddleLow - f0) / (f1 - f0);
        double t1 = (kMiddleHigh - f0) / (f1 - f0);
        if (t0 > t1) std::swap(t0, t1);
        t0 = std::max(t0, 0.0);
        t1 = std::min(t1, 1.0);
        if (t0 <= t1) spans.push_back({k, t0, t1});
    }
    if (spans.empty()) return r;
    r.anyMiddle = true;
    const std::size_t stride = std::max<std::size_t>(1, plane / kSampledColumns);
    const std::size_t members = e.memberCount();
    for (std::size_t column = 0; column < plane; column += stride) ++r.columns;
    r.low.assign(r.columns * members, std::numeric_limits<float>::quiet_NaN());
    r.high = r.low;
    std::size_t c = 0;
    for (std::size_t column = 0; column < plane; column += stride, ++c) {
        for (std::size_t m = 0; m < members; ++m) {
            const float* v = e.members[m].values.data() + column;
            float low = std::numeric_limits<float>::infinity();
            float high = -low;
            bool missing = false;
            for (const Span& s : spans) {
                const float a = v[s.k * plane];
                const float b = v[(s.k + 1) * plane];
                if (a != a || b != b) {
                    missing = true;
                    break;
                }
                const auto at = [a, b](double t) { return static_cast<float>(a + t * (b - a)); };
                low = std::min({low, at(s.t0), at(s.t1)});
                high = std::max({high, at(s.t0), at(s.t1)});
            }
            if (missing) continue;
            r.low[c * members + m] = low;
            r.high[c * members + m] = high;
        }
    }
    return r;
}

double membersCrossingTheMiddle(const MiddleRanges& r, std::size_t members, float isovalue) {
    if (!r.anyMiddle) return 1.0;  // no height to stand in: the condition says nothing
    if (members == 0 || r.columns == 0) return 0.0;
    std::vector<std::size_t> crossed(members, 0);
    for (std::size_t c = 0; c < r.columns; ++c) {
        const float* low = r.low.data() + c * members;
        const float* high = r.high.data() + c * members;
        for (std::size_t m = 0; m < members; ++m) {
            crossed[m] += static_cast<std::size_t>(low[m] < isovalue && isovalue < high[m]);
        }
    }
    const double least = std::max(1.0, kLeastShare * static_cast<double>(r.columns));
    const auto with = std::count_if(crossed.begin(), crossed.end(), [least](std::size_t n) {
        return static_cast<double>(n) >= least;
    });
    return static_cast<double>(with) / static_cast<double>(members);
}

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
    for (int p = 10; p <= 45; p += 5) {
        candidates.push_back({p, percentile(s.histogram, s.minimum, s.maximum, p / 100.0)});
    }
    const std::size_t points = e.grid.pointCount();
    const std::size_t members = e.memberCount();
    if (points == 0 || members == 0) return candidates;
    const std::size_t stride = std::max<std::size_t>(1, points / kSampledPoints);
    // The sampled points' values gathered once, point by point (a few MB): the candidates then
    // read them in order instead of each reading every member at every sampled point again.
    const MiddleRanges middle = middleRanges(e);
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
        c.membersInMiddle = membersCrossingTheMiddle(middle, members, c.isovalue);
        c.disagreement = sampled > 0 ? disagreement / static_cast<double>(sampled) : 0.0;
    }
    return candidates;
}

namespace {

// Of these candidates, those with enough members with a surface (and, with `middle`, in the
// middle half) and a disagreement near the largest: the one nearest the paper's percentile, the
// higher of two equally near. Null when none qualifies.
const IsovalueCandidate* nearestThePaper(const std::vector<const IsovalueCandidate*>& candidates,
                                         bool middle) {
    const auto qualifies = [middle](const IsovalueCandidate& c) {
        return c.membersWithSurface >= kMostMembers &&
               (!middle || c.membersInMiddle >= kMostMembers);
    };
    double best = 0.0;
    for (const IsovalueCandidate* c : candidates) {
        if (qualifies(*c)) best = std::max(best, c->disagreement);
    }
    if (best <= 0.0) return nullptr;
    const auto distance = [](const IsovalueCandidate& x) {
        return 2 * std::abs(x.percentile - kPaperPercentile) -
               (x.percentile > kPaperPercentile ? 1 : 0);
    };
    const IsovalueCandidate* chosen = nullptr;
    for (const IsovalueCandidate* c : candidates) {
        if (!qualifies(*c) || c->disagreement < kNearBest * best) continue;
        if (chosen == nullptr || distance(*c) < distance(*chosen)) chosen = c;
    }
    return chosen;
}

}  // namespace

float defaultIsovalue(const data::Ensemble& e, const FieldStatistics& s) {
    if (s.validCount == 0) return 0.5F * (s.minimum + s.maximum);
    const std::vector<IsovalueCandidate> candidates = isovalueCandidates(e, s);
    std::vector<const IsovalueCandidate*> upper, all;
    for (const IsovalueCandidate& c : candidates) {
        all.push_back(&c);
        if (c.percentile >= 50) upper.push_back(&c);
    }
    // The upper percentiles with a surface in the middle half; then the lower ones; then, where
    // no surface stands there, the upper percentiles as the paper chose.
    for (const auto& [tier, middle] :
         {std::pair{&upper, true}, std::pair{&all, true}, std::pair{&upper, false}}) {
        if (const IsovalueCandidate* chosen = nearestThePaper(*tier, middle))
            return chosen->isovalue;
    }
    return percentile(s.histogram, s.minimum, s.maximum, 0.9);
}

}  // namespace ensil::prep

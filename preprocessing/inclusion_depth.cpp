#include "preprocessing/inclusion_depth.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>

#include "data/error.h"
#include "preprocessing/similarity.h"

namespace ensil::prep {

namespace {

constexpr std::size_t kWordBits = 64;

// Missing values (NaN, and +inf, which openEnsemble makes NaN anyway) are never inside; -inf
// fails the comparison by itself.
bool inside(float value, float isovalue) {
    return value > isovalue && value < std::numeric_limits<float>::infinity();
}

// Member m's inside set as bits, point p at bit p % 64 of word p / 64; the last word's unused
// bits stay 0, so they never count.
void packInsideSet(const float* values, std::size_t points, float isovalue, std::uint64_t* bits) {
    const std::size_t fullWords = points / kWordBits;
    for (std::size_t w = 0; w < fullWords; ++w) {
        const float* v = values + w * kWordBits;
        std::uint64_t word = 0;
        for (std::size_t b = 0; b < kWordBits; ++b) {
            word |= static_cast<std::uint64_t>(inside(v[b], isovalue)) << b;
        }
        bits[w] = word;
    }
    if (fullWords * kWordBits < points) {
        std::uint64_t word = 0;
        for (std::size_t p = fullWords * kWordBits; p < points; ++p) {
            word |= static_cast<std::uint64_t>(inside(values[p], isovalue)) << (p % kWordBits);
        }
        bits[fullWords] = word;
    }
}

// Built twice, and the one for the processor chosen when the program loads: the baseline
// x86-64 has no popcount instruction, and libgcc's routine in its place took most of the
// boxplot's time (1225 pairs of 8192 words on the demo).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define ENSIL_WITH_POPCOUNT_INSTRUCTION __attribute__((target_clones("popcnt", "default")))
#else
#define ENSIL_WITH_POPCOUNT_INSTRUCTION
#endif

ENSIL_WITH_POPCOUNT_INSTRUCTION
std::size_t countBits(const std::uint64_t* bits, std::size_t words) {
    std::size_t count = 0;
    for (std::size_t w = 0; w < words; ++w)
        count += static_cast<std::size_t>(std::popcount(bits[w]));
    return count;
}

ENSIL_WITH_POPCOUNT_INSTRUCTION
std::size_t countCommonBits(const std::uint64_t* a, const std::uint64_t* b, std::size_t words) {
    std::size_t count = 0;
    for (std::size_t w = 0; w < words; ++w) {
        count += static_cast<std::size_t>(std::popcount(a[w] & b[w]));
    }
    return count;
}

}  // namespace

double linearQuantile(std::span<const double> sorted, double q) {
    if (sorted.empty() || !(q >= 0.0 && q <= 1.0)) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "a quantile needs at least one value and a fraction in [0, 1]");
    }
    const double h = static_cast<double>(sorted.size() - 1) * q;
    const auto below = static_cast<std::size_t>(std::floor(h));
    if (below + 1 >= sorted.size()) return sorted.back();
    return sorted[below] + (h - static_cast<double>(below)) * (sorted[below + 1] - sorted[below]);
}

ContourBoxplot computeContourBoxplot(const data::Ensemble& ensemble, float isovalue,
                                     const std::stop_token& stop, const data::Progress& progress) {
    checkDistanceArguments(ensemble, isovalue, "compute the contour boxplot");
    const std::size_t n = ensemble.memberCount();
    const std::size_t points = ensemble.grid.pointCount();
    const std::size_t words = (points + kWordBits - 1) / kWordBits;

    ContourBoxplot box;
    box.isovalue = isovalue;
    std::vector<std::uint64_t> bits(n * words);
    box.insidePoints.resize(n);
    // Members, then rows of pairs, on every core: each writes only its own entries, so the
    // counts (integers) are what one thread gives.
    data::PartsProgress membersDone(progress, n, 0.0, 0.5);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t m) {
        data::throwIfStopped(stop);
        std::uint64_t* set = bits.data() + m * words;
        packInsideSet(ensemble.members[m].values.data(), points, isovalue, set);
        box.insidePoints[m] = countBits(set, words);
        membersDone.partDone();
    });

    // |B_i & B_j| for i < j; |B_i \ B_j| = |B_i| - |B_i & B_j|, so half the pairs suffice.
    std::vector<std::size_t> common(n * n, 0);
    data::PartsProgress rowsDone(progress, n, 0.5, 0.95);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        data::throwIfStopped(stop);
        for (std::size_t j = i + 1; j < n; ++j) {
            common[i * n + j] = common[j * n + i] =
                countCommonBits(bits.data() + i * words, bits.data() + j * words, words);
        }
        rowsDone.partDone();
    });

    // e(i in j) = 1 - |B_i \ B_j| / |B_i|, 1 when B_i is empty.
    const auto containment = [&](std::size_t i, std::size_t j) {
        const std::size_t size = box.insidePoints[i];
        if (size == 0) return 1.0;
        return 1.0 - static_cast<double>(size - common[i * n + j]) / static_cast<double>(size);
    };
    box.depth.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        if (box.insidePoints[i] == 0) continue;  // no surface: depth 0
        if (n == 1) {
            box.depth[i] = 1.0;  // nothing to compare with: as deep as a member can be
            continue;
        }
        double inOthers = 0.0;  // sum over j of e(i in j)
        double othersIn = 0.0;  // sum over j of e(j in i)
        for (std::size_t j = 0; j < n; ++j) {
            if (j == i) continue;
            inOthers += containment(i, j);
            othersIn += containment(j, i);
        }
        box.depth[i] = std::min(inOthers, othersIn) / static_cast<double>(n - 1);
    }

    box.bandMembers = bandMembersOf(box.depth);
    box.median = box.bandMembers.front();

    // Sun and Genton's fence, 1.5 interquartile ranges below the first quartile, with numpy's
    // default ("linear") quartiles. Depth measures centrality, so only the low side has outliers.
    std::vector<double> sorted = box.depth;
    std::sort(sorted.begin(), sorted.end());
    const double q1 = linearQuantile(sorted, 0.25);
    const double q3 = linearQuantile(sorted, 0.75);
    box.lowerFence = q1 - 1.5 * (q3 - q1);
    for (std::size_t m = 0; m < n; ++m) {
        if (box.depth[m] < box.lowerFence) box.outliers.push_back(m);
    }
    data::report(progress, 1.0);
    return box;
}

std::vector<std::size_t> bandMembersOf(std::span<const double> depth) {
    // Deepest first; a stable sort keeps equals in index order.
    std::vector<std::size_t> order(depth.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
    order.resize((depth.size() + 1) / 2);
    return order;
}

}  // namespace ensil::prep

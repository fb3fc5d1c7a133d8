#include "preprocessing/ensemble_statistics.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "data/error.h"
#include "preprocessing/similarity.h"

namespace ensil::prep {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr float kMinusInfinity = -std::numeric_limits<float>::infinity();

// A corner's side of c as a bit, so that the OR over a cell's 8 corners says it all: 3 (both
// bits) straddles, 1 or 2 does not, and anything with kMissing has a corner without a value.
constexpr std::uint8_t kBelow = 1;  // finite and <= c
constexpr std::uint8_t kAbove = 2;  // finite and > c
constexpr std::uint8_t kMissing = 4;

std::uint8_t side(float value, float isovalue) {
    if (!std::isfinite(value)) return kMissing;
    return value > isovalue ? kAbove : kBelow;
}

void checkMembers(const data::Ensemble& ensemble, std::span<const std::size_t> members) {
    if (members.empty()) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "no members to compute the ensemble statistics of: choose at least one");
    }
    const std::size_t n = ensemble.memberCount();
    std::vector<bool> seen(n, false);
    for (const std::size_t m : members) {
        if (m >= n) {
            throw data::Error(data::ErrorKind::InvalidArgument,
                              "member index " + std::to_string(m) + " is out of range: the " +
                                  "ensemble has " + std::to_string(n) + " members (0 to " +
                                  std::to_string(n - 1) + ")");
        }
        if (seen[m]) {
            throw data::Error(data::ErrorKind::InvalidArgument,
                              "member " + std::to_string(m) + " ('" + ensemble.members[m].name +
                                  "') is listed twice in the members to summarise");
        }
        seen[m] = true;
    }
}

}  // namespace

EnsembleStatisticsAccumulator::EnsembleStatisticsAccumulator(const data::Grid& grid, float isovalue)
    : m_nx(grid.nx()), m_ny(grid.ny()), m_nz(grid.nz()), m_isovalue(isovalue) {
    if (!std::isfinite(isovalue)) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "the isovalue of the ensemble statistics must be a finite number");
    }
    if (grid.pointCount() == 0) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "cannot compute ensemble statistics on a grid without points");
    }
    const std::size_t points = grid.pointCount();
    m_count.assign(points, 0);
    m_above.assign(points, 0);
    m_mean.assign(points, 0.0);
    m_squares.assign(points, 0.0);
    m_minimum.assign(points, kInfinity);
    m_maximum.assign(points, kMinusInfinity);
    m_cellValid.assign(cellCount(grid), 0);
    m_cellCrossing.assign(cellCount(grid), 0);
    m_levelCodes.resize(m_nx * m_ny);
}

void EnsembleStatisticsAccumulator::add(std::span<const float> member) {
    for (std::size_t k = 0; k < m_nz; ++k) addLevel(member, k);
}

void EnsembleStatisticsAccumulator::addLevel(std::span<const float> member, std::size_t k) {
    addLevel(member, k, m_levelCodes);
}

void EnsembleStatisticsAccumulator::addLevel(std::span<const float> member, std::size_t k,
                                             std::span<std::uint8_t> scratch) {
    const std::size_t level = m_nx * m_ny;
    if (scratch.size() < level) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "the statistics' scratch holds " + std::to_string(scratch.size()) +
                              " bytes where a level has " + std::to_string(level) + " points");
    }
    if (member.size() != level * m_nz) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "a member with " + std::to_string(member.size()) +
                              " values cannot be added to statistics on a grid of " +
                              std::to_string(level * m_nz) + " points");
    }
    if (k >= m_nz) {
        throw data::Error(data::ErrorKind::InvalidArgument, "level " + std::to_string(k) +
                                                                " is outside the grid's " +
                                                                std::to_string(m_nz) + " levels");
    }
    const float c = m_isovalue;
    const float* values = member.data() + k * level;
    // Local pointers: a store through one of them cannot then make the compiler reload the
    // vectors' data pointers (the byte codes below may alias anything).
    std::uint32_t* count = m_count.data() + k * level;
    std::uint32_t* above = m_above.data() + k * level;
    float* minimum = m_minimum.data() + k * level;
    float* maximum = m_maximum.data() + k * level;
    double* mean = m_mean.data() + k * level;
    double* squares = m_squares.data() + k * level;
    // Two loops without branches, so that the compiler vectorises them (a missing value
    // selects values that change nothing); each touches few arrays, so that the checks for
    // overlapping arrays stay within what the vectoriser does at run time.
    for (std::size_t q = 0; q < level; ++q) {
        const float v = values[q];
        const bool valid = std::isfinite(v);
        count[q] += valid ? 1U : 0U;
        above[q] += valid && v > c ? 1U : 0U;
        minimum[q] = std::min(minimum[q], valid ? v : kInfinity);
        maximum[q] = std::max(maximum[q], valid ? v : kMinusInfinity);
    }
    // Welford's update, with n already counting this value: after n values, mean is their mean
    // and squares the sum of squared deviations from it, each step exact up to one rounding,
    // whatever the offset of the values. A missing value gives x = mean, so delta = 0.
    for (std::size_t q = 0; q < level; ++q) {
        const float v = values[q];
        const double x = std::isfinite(v) ? static_cast<double>(v) : mean[q];
        const double delta = x - mean[q];
        const double newMean = mean[q] + delta / static_cast<double>(std::max(count[q], 1U));
        mean[q] = newMean;
        squares[q] += delta * (x - newMean);
    }
    if (k + 1 == m_nz) return;  // no cells above the top level
    // The cells between levels k and k + 1: OR the two levels' codes point by point, then each
    // cell ORs its 4 columns.
    const float* upper = values + level;
    std::uint8_t* codes = scratch.data();
    for (std::size_t q = 0; q < level; ++q) {
        codes[q] = static_cast<std::uint8_t>(side(values[q], c) | side(upper[q], c));
    }
    const std::size_t cx = m_nx - 1;
    const std::size_t cy = m_ny - 1;
    std::uint32_t* cellValid = m_cellValid.data() + k * cy * cx;
    std::uint32_t* cellCrossing = m_cellCrossing.data() + k * cy * cx;
    for (std::size_t j = 0; j < cy; ++j) {
        const std::uint8_t* row = codes + j * m_nx;
        const std::uint8_t* next = row + m_nx;
        std::uint32_t* valid = cellValid + j * cx;
        std::uint32_t* crossing = cellCrossing + j * cx;
        for (std::size_t i = 0; i < cx; ++i) {
            const unsigned corners = row[i] | row[i + 1] | next[i] | next[i + 1];
            // bool to unsigned, not `? 1U : 0U`, which GCC 12 leaves as a branch here.
            valid[i] += static_cast<unsigned>(corners < kMissing);
            crossing[i] += static_cast<unsigned>(corners == (kBelow | kAbove));
        }
    }
}

EnsembleStatistics EnsembleStatisticsAccumulator::result() const {
    EnsembleStatistics s;
    s.isovalue = m_isovalue;
    const std::size_t points = m_count.size();
    for (data::FieldValues* field :
         {&s.count, &s.mean, &s.stddev, &s.minimum, &s.maximum, &s.range, &s.exceedance}) {
        field->resize(points);
    }
    for (std::size_t p = 0; p < points; ++p) {
        const std::uint32_t n = m_count[p];
        s.count[p] = static_cast<float>(n);
        if (n == 0) {
            s.mean[p] = s.stddev[p] = s.minimum[p] = s.maximum[p] = s.range[p] = s.exceedance[p] =
                kNaN;
            continue;
        }
        s.mean[p] = static_cast<float>(m_mean[p]);
        // Each of Welford's terms is >= 0 in exact arithmetic; the clamp only guards rounding.
        s.stddev[p] =
            n < 2 ? kNaN : static_cast<float>(std::sqrt(std::max(0.0, m_squares[p]) / (n - 1)));
        s.minimum[p] = m_minimum[p];
        s.maximum[p] = m_maximum[p];
        s.range[p] = m_maximum[p] - m_minimum[p];
        s.exceedance[p] = static_cast<float>(static_cast<double>(m_above[p]) / n);
    }
    s.levelCrossing.resize(m_cellValid.size());
    for (std::size_t cell = 0; cell < m_cellValid.size(); ++cell) {
        const std::uint32_t n = m_cellValid[cell];
        s.levelCrossing[cell] =
            n == 0 ? kNaN : static_cast<float>(static_cast<double>(m_cellCrossing[cell]) / n);
    }
    return s;
}

EnsembleStatistics computeEnsembleStatistics(const data::Ensemble& ensemble, float isovalue,
                                             const std::stop_token& stop,
                                             const data::Progress& progress) {
    std::vector<std::size_t> all(ensemble.memberCount());
    std::iota(all.begin(), all.end(), std::size_t{0});
    return computeEnsembleStatistics(ensemble, isovalue, all, stop, progress);
}

EnsembleStatistics computeEnsembleStatistics(const data::Ensemble& ensemble, float isovalue,
                                             std::span<const std::size_t> members,
                                             const std::stop_token& stop,
                                             const data::Progress& progress) {
    checkDistanceArguments(ensemble, isovalue, "compute the ensemble statistics");
    checkMembers(ensemble, members);
    EnsembleStatisticsAccumulator accumulator(ensemble.grid, isovalue);
    // Level by level, every member through each level: the running sums of one level (about
    // 40 bytes a point) stay in cache instead of streaming the whole grid's once per member.
    // Levels on threads of their own (their sums are disjoint; each level takes the members in
    // the same order, so the result does not depend on the threads).
    const std::size_t levels = ensemble.grid.nz();
    data::PartsProgress levelsDone(progress, levels, 0.0, 0.95);
    tbb::parallel_for(std::size_t{0}, levels, [&](std::size_t k) {
        std::vector<std::uint8_t> scratch(ensemble.grid.nx() * ensemble.grid.ny());
        for (const std::size_t m : members) {
            data::throwIfStopped(stop);
            accumulator.addLevel(ensemble.members[m].values, k, scratch);
        }
        levelsDone.partDone();
    });
    data::throwIfStopped(stop);
    EnsembleStatistics result = accumulator.result();
    result.members.assign(members.begin(), members.end());
    data::report(progress, 1.0);
    return result;
}

}  // namespace ensil::prep

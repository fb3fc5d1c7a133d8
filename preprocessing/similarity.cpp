#include "preprocessing/similarity.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>

#include "data/error.h"

namespace ensil::prep {
namespace {

// Column-major: one column per member, one row per grid point of the current block, so a
// member's values are read and written contiguously.
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic>;

// Points per block: a block matrix (points x members, double) of about 256 KiB stays in a
// core's L2 cache while the matrix products read it (4 MiB blocks spilled to memory and cost
// as much in traffic as the products themselves), keeps a block well under a millisecond (the
// stop token is checked between blocks), and still gives the products inner dimensions of
// hundreds of points, long enough to run at full speed.
std::size_t blockRows(std::size_t members) {
    constexpr std::size_t kBlockBytes = std::size_t{256} << 10;
    return std::clamp<std::size_t>(kBlockBytes / (members * sizeof(double)), 256, 65536);
}

// Blocks per part: the points are cut into parts of this many blocks whatever the number of
// threads, each part summed on its own and the parts merged in order, so the sums (and their
// rounding) do not depend on how many threads ran them.
constexpr std::size_t kBlocksPerPart = 64;

// The three running sums of DistanceSums, viewed as matrices over its one array. With
// S_i = M_i s_i the masked square-root distances and M_i the validity masks:
//   cross(i, j)   = sum_x S_i S_j        (lower triangle only)
//   squares(i, j) = sum_x S_i^2 M_j      (full matrix; not symmetric)
//   common(i, j)  = sum_x M_i M_j = m_ij (lower triangle only)
// so that sum_x M_i M_j (s_i - s_j)^2 = squares(i, j) + squares(j, i) - 2 cross(i, j).
template <typename MatrixType>  // Matrix, or const Matrix to read
struct PairSumsView {
    using Map = Eigen::Map<MatrixType>;
    Map cross, squares, common;

    PairSumsView(std::conditional_t<std::is_const_v<MatrixType>, const double*, double*> data,
                 Eigen::Index n)
        : cross(data, n, n), squares(data + n * n, n, n), common(data + 2 * n * n, n, n) {}
};

// Fills s (rows x members) with the square-root distances of the points [first, first + rows)
// of every member, 0 where a value is missing. Returns whether any of these points is missing
// in any member; only then is the mask (1 where valid) filled too, since a block with nothing
// missing needs none.
bool fillBlock(std::span<const std::span<const float>> members, double isovalue, std::size_t first,
               std::size_t rows, Matrix& s, Matrix& mask) {
    bool missing = false;
    for (std::size_t m = 0; m < members.size(); ++m) {
        const float* values = members[m].data() + first;
        double* sColumn = s.col(static_cast<Eigen::Index>(m)).data();
        // Two plain loops rather than one, so that each vectorises (GCC does not vectorise the
        // root beside a flag gathered over the points): NaN and infinity fail the comparisons.
        for (std::size_t p = 0; p < rows; ++p) {
            const double diff = std::abs(static_cast<double>(values[p]) - isovalue);
            const bool valid = diff <= std::numeric_limits<double>::max();
            sColumn[p] = std::sqrt(valid ? diff : 0.0);
        }
        std::int32_t invalid = 0;
        for (std::size_t p = 0; p < rows; ++p) {
            invalid |= std::abs(values[p]) <= std::numeric_limits<float>::max() ? 0 : 1;
        }
        missing |= invalid != 0;
    }
    if (!missing) return false;
    for (std::size_t m = 0; m < members.size(); ++m) {
        const float* values = members[m].data() + first;
        double* maskColumn = mask.col(static_cast<Eigen::Index>(m)).data();
        for (std::size_t p = 0; p < rows; ++p) {
            maskColumn[p] = std::isfinite(values[p]) ? 1.0 : 0.0;
        }
    }
    return true;
}

void accumulateBlock(const Matrix& s, const Matrix& mask, bool missing,
                     PairSumsView<Matrix>& sums) {
    sums.cross.selfadjointView<Eigen::Lower>().rankUpdate(s.transpose());
    if (missing) {
        const Matrix squared = s.array().square().matrix();
        sums.squares.noalias() += squared.transpose() * mask;
        sums.common.selfadjointView<Eigen::Lower>().rankUpdate(mask.transpose());
    } else {
        // Every mask is all ones: the two mask products reduce to column sums and the point
        // count, which saves two of the three matrix products.
        const Eigen::VectorXd columnSums = s.array().square().colwise().sum().transpose();
        sums.squares.colwise() += columnSums;
        sums.common.array() += static_cast<double>(s.rows());
    }
}

// Members that share no valid point cannot be compared. An infinite distance would merge them
// at an infinite height, which no JSON reader or SciPy accepts; they are placed as far apart as
// the farthest pair that can be compared, so they merge last among equals (METHODS.md
// section 7).
void placePairsWithoutOverlap(DistanceMatrix& m) {
    if (m.pairsWithoutOverlap.empty()) return;
    std::sort(m.pairsWithoutOverlap.begin(), m.pairsWithoutOverlap.end());
    const std::size_t pairs = m.size * (m.size - 1) / 2;
    if (m.pairsWithoutOverlap.size() == pairs) {
        throw data::Error(data::ErrorKind::AllValuesMissing,
                          "no two members have a valid value at the same grid point, so no "
                          "two can be compared");
    }
    double farthest = 0.0;
    for (std::size_t i = 0; i < m.size; ++i) {
        for (std::size_t j = 0; j < i; ++j) farthest = std::max(farthest, m.at(i, j));
    }
    for (const auto& [i, j] : m.pairsWithoutOverlap) {
        m.values[i * m.size + j] = m.values[j * m.size + i] = farthest;
    }
}

}  // namespace

void checkDistanceArguments(const data::Ensemble& ensemble, float isovalue,
                            const std::string& what) {
    if (ensemble.members.empty()) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "cannot " + what + " of an ensemble with no members");
    }
    if (!std::isfinite(isovalue)) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "the isovalue to " + what + " must be a finite number");
    }
    const std::size_t points = ensemble.grid.pointCount();
    for (const data::Member& member : ensemble.members) {
        if (member.values.size() != points) {
            throw data::Error(data::ErrorKind::InvalidArgument,
                              "member '" + member.name + "' has " +
                                  std::to_string(member.values.size()) +
                                  " values but the grid has " + std::to_string(points) + " points");
        }
    }
}

DistanceSums::DistanceSums(std::size_t members, float isovalue)
    : m_members(members), m_isovalue(isovalue), m_sums(3 * members * members + 1, 0.0) {}

void DistanceSums::add(std::span<const std::span<const float>> memberValues,
                       const std::stop_token& stop, const data::Progress& progress) {
    if (memberValues.size() != m_members) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "the distance sums were made for " + std::to_string(m_members) +
                              " members but are given " + std::to_string(memberValues.size()));
    }
    if (m_members == 0) return;
    const std::size_t points = memberValues.front().size();
    for (std::size_t m = 1; m < m_members; ++m) {
        if (memberValues[m].size() != points) {
            throw data::Error(
                data::ErrorKind::InvalidArgument,
                "member " + std::to_string(m) + " gives " + std::to_string(memberValues[m].size()) +
                    " values to the distance sums where member 0 gives " + std::to_string(points));
        }
    }
    if (points == 0) return;
    const auto n = static_cast<Eigen::Index>(m_members);
    const std::size_t maxRows = std::min(blockRows(m_members), points);
    const std::size_t blocks = (points + maxRows - 1) / maxRows;
    const std::size_t parts = (blocks + kBlocksPerPart - 1) / kBlocksPerPart;
    // Each part sums its points from zero into its own array (the three n x n matrices), and
    // the parts are added to these sums in order after all have run.
    const std::size_t matrixValues = m_sums.size() - 1;
    std::vector<std::vector<double>> partSums(parts);
    // The block matrices of each thread, made once and reused by every part it runs.
    struct BlockMatrices {
        Matrix s, mask;
    };
    tbb::enumerable_thread_specific<BlockMatrices> scratch;
    data::PartsProgress blocksProgress(progress, blocks);
    tbb::parallel_for(std::size_t{0}, parts, [&](std::size_t part) {
        auto& [s, mask] = scratch.local();
        partSums[part].assign(matrixValues, 0.0);
        PairSumsView<Matrix> sums(partSums[part].data(), n);
        const std::size_t end = std::min(points, (part + 1) * kBlocksPerPart * maxRows);
        for (std::size_t first = part * kBlocksPerPart * maxRows; first < end; first += maxRows) {
            data::throwIfStopped(stop);
            const auto rows = static_cast<Eigen::Index>(std::min(maxRows, end - first));
            if (s.rows() != rows) {  // the first block on this thread, or the last, shorter one
                s.resize(rows, n);
                mask.resize(rows, n);
            }
            const bool missing =
                fillBlock(memberValues, m_isovalue, first, static_cast<std::size_t>(rows), s, mask);
            accumulateBlock(s, mask, missing, sums);
            blocksProgress.partDone();
        }
    });
    for (const std::vector<double>& part : partSums) {
        for (std::size_t k = 0; k < matrixValues; ++k) m_sums[k] += part[k];
    }
    m_sums.back() += static_cast<double>(points);
}

void DistanceSums::merge(const DistanceSums& other) {
    if (other.m_members != m_members || !(other.m_isovalue == m_isovalue)) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "cannot merge distance sums of " + std::to_string(other.m_members) +
                              " members at isovalue " + std::to_string(other.m_isovalue) +
                              " into sums of " + std::to_string(m_members) +
                              " members at isovalue " + std::to_string(m_isovalue));
    }
    for (std::size_t k = 0; k < m_sums.size(); ++k) m_sums[k] += other.m_sums[k];
}

DistanceSums DistanceSums::subset(std::span<const std::size_t> keep) const {
    DistanceSums out(keep.size(), m_isovalue);
    const std::size_t n = m_members, k = keep.size();
    for (std::size_t a = 0; a < k; ++a) {
        if (keep[a] >= n) {
            throw data::Error(data::ErrorKind::InvalidArgument,
                              "member " + std::to_string(keep[a]) + " is not among the " +
                                  std::to_string(n) + " of the distance sums");
        }
    }
    // Column-major n x n matrices one after another, as PairSumsView reads them.
    for (std::size_t matrix = 0; matrix < 3; ++matrix) {
        const double* from = m_sums.data() + matrix * n * n;
        double* to = out.m_sums.data() + matrix * k * k;
        for (std::size_t b = 0; b < k; ++b) {
            for (std::size_t a = 0; a < k; ++a) to[a + b * k] = from[keep[a] + keep[b] * n];
        }
    }
    out.m_sums.back() = points();
    return out;
}

DistanceMatrix DistanceSums::finish() const {
    const std::size_t n = m_members;
    DistanceMatrix result;
    result.size = n;
    result.values.assign(n * n, 0.0);
    if (n == 0) return result;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            const double d = distance(i, j);
            if (std::isfinite(d)) {
                result.values[i * n + j] = result.values[j * n + i] = d;
            } else {
                result.pairsWithoutOverlap.emplace_back(j, i);
            }
        }
    }
    placePairsWithoutOverlap(result);
    return result;
}

double DistanceSums::distance(std::size_t i, std::size_t j) const {
    if (i == j) return 0.0;
    // The matrices' lower triangles hold the symmetric sums.
    const auto lower = static_cast<Eigen::Index>(std::max(i, j));
    const auto upper = static_cast<Eigen::Index>(std::min(i, j));
    const PairSumsView<const Matrix> sums(m_sums.data(), static_cast<Eigen::Index>(m_members));
    const double count = sums.common(lower, upper);
    if (!(count > 0.0)) return std::numeric_limits<double>::infinity();
    // The expanded form loses the exact zero of identical members to rounding; clamp the tiny
    // negative values that can result.
    const double sum = std::max(0.0, sums.squares(lower, upper) + sums.squares(upper, lower) -
                                         2.0 * sums.cross(lower, upper));
    return sum / count;
}

namespace {

// The sums over every grid point of the members, then of `more` fields on the grid (members
// n, n + 1, ... of the sums). The arguments are checked by the caller.
DistanceSums sumOverTheGrid(const data::Ensemble& ensemble,
                            std::span<const std::span<const float>> more, float isovalue,
                            const std::stop_token& stop, const data::Progress& progress) {
    const std::size_t points = ensemble.grid.pointCount();
    // All points in one add(): its block matrices are allocated once (a fresh 4 MiB pair for
    // every block cost more in page faults than the products themselves).
    DistanceSums sums(ensemble.memberCount() + more.size(), isovalue);
    std::vector<std::span<const float>> values;
    values.reserve(ensemble.memberCount() + more.size());
    for (const data::Member& member : ensemble.members) {
        values.emplace_back(member.values.data(), points);
    }
    values.insert(values.end(), more.begin(), more.end());
    sums.add(values, stop, progress);
    data::throwIfStopped(stop);
    return sums;
}

}  // namespace

DistanceMatrix computeDistanceMatrix(const data::Ensemble& ensemble, float isovalue,
                                     const std::stop_token& stop, const data::Progress& progress) {
    checkDistanceArguments(ensemble, isovalue, "compare the members");
    DistanceMatrix result = sumOverTheGrid(ensemble, {}, isovalue, stop, progress).finish();
    data::report(progress, 1.0);
    return result;
}

DistancesAndReference computeDistancesAndReference(const data::Ensemble& ensemble,
                                                   std::span<const float> reference, float isovalue,
                                                   const std::stop_token& stop,
                                                   const data::Progress& progress) {
    checkDistanceArguments(ensemble, isovalue, "compare the members");
    const std::size_t n = ensemble.memberCount();
    const std::size_t points = ensemble.grid.pointCount();
    if (reference.size() != points) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "the reference field has " + std::to_string(reference.size()) +
                              " values but the grid has " + std::to_string(points) + " points");
    }
    // The reference is member n of the sums.
    const DistanceSums sums = sumOverTheGrid(ensemble, {&reference, 1}, isovalue, stop, progress);
    DistancesAndReference result;
    result.toReference.reserve(n);
    for (std::size_t i = 0; i < n; ++i) result.toReference.push_back(sums.distance(i, n));
    std::vector<std::size_t> members(n);
    std::iota(members.begin(), members.end(), std::size_t{0});
    result.matrix = sums.subset(members).finish();
    data::report(progress, 1.0);
    return result;
}

std::string pairsWithoutOverlapWarning(const data::Ensemble& ensemble,
                                       const DistanceMatrix& distances) {
    const auto& pairs = distances.pairsWithoutOverlap;
    if (pairs.empty()) return {};
    constexpr std::size_t kNamed = 4;
    std::string text = pairs.size() == 1 ? "one pair of members shares"
                                         : std::to_string(pairs.size()) + " pairs of members share";
    text += " no grid point where both have a valid value (";
    for (std::size_t p = 0; p < std::min(pairs.size(), kNamed); ++p) {
        if (p > 0) text += ", ";
        text += "'" + ensemble.members[pairs[p].first].name + "' and '" +
                ensemble.members[pairs[p].second].name + "'";
    }
    if (pairs.size() > kNamed) text += ", and " + std::to_string(pairs.size() - kNamed) + " more";
    const auto [i, j] = pairs.front();
    char distance[32];
    std::snprintf(distance, sizeof distance, "%.4g", distances.at(i, j));
    text +=
        "): they cannot be compared, so each such pair is placed as far apart as the farthest "
        "pair that can be (distance " +
        std::string(distance) + ")";
    return text;
}

}  // namespace ensil::prep

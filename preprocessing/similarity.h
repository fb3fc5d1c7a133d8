// Pairwise distances between ensemble members for one isovalue (METHODS.md section 7), the
// input of the member clustering:
//   d(i, j) = sum_x ( sqrt|f_i(x) - mu| - sqrt|f_j(x) - mu| )^2 / m_ij
// over the m_ij grid points valid in both members. The square root weights changes near the
// isovalue more than far from it. Pure function; runs on any thread; the result is a plain value.
#pragma once

#include <cstddef>
#include <span>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "data/ensemble.h"
#include "data/job.h"

namespace ensil::prep {

// A symmetric N x N matrix of member distances with a zero diagonal, stored row-major.
struct DistanceMatrix {
    std::size_t size = 0;        // N, the number of members
    std::vector<double> values;  // size * size entries, values[i * size + j] = d(i, j)
    // The pairs (i < j) that share no valid grid point, whose distance was set by the rule of
    // computeDistanceMatrix rather than measured; empty when every pair overlaps.
    std::vector<std::pair<std::size_t, std::size_t>> pairsWithoutOverlap;

    [[nodiscard]] double at(std::size_t i, std::size_t j) const { return values[i * size + j]; }
};

// The distance matrix's sums over some of the grid points (METHODS.md section 7): for every pair
// (i, j) the sums of s_i s_j, s_i^2 and s_j^2 and the count m_ij over the points valid in both.
// Sums over disjoint sets of points add up, so any partition of the grid (blocks in one process,
// slabs read one after another, ranks of an MPI job) gives the whole grid's matrix: each part
// adds its points, the parts are merged (merge() here, or a sum-reduction of raw() between
// processes), and finish() divides. Accumulated in double; not thread-safe (one per thread).
class DistanceSums {
public:
    DistanceSums() = default;
    DistanceSums(std::size_t members, float isovalue);

    [[nodiscard]] std::size_t members() const { return m_members; }
    [[nodiscard]] float isovalue() const { return m_isovalue; }
    // Grid points added so far (over every merged part).
    [[nodiscard]] double points() const { return m_sums.empty() ? 0.0 : m_sums.back(); }

    // Adds the same `points` consecutive grid points of every member: memberValues[m] holds
    // member m's values there (NaN or infinite where missing). The points are summed in parts
    // of a fixed size on every thread of the pool and the parts merged in order, so the result
    // does not depend on the number of threads. Throws data::Cancelled between blocks of about
    // 256 KiB; data::Error(InvalidArgument) when the count of members or of values differs from
    // what the sums were made for.
    // `progress` hears the share of the points added after each block (from the pool's threads,
    // one at a time).
    void add(std::span<const std::span<const float>> memberValues, const std::stop_token& stop = {},
             const data::Progress& progress = {});
    // Adds another part's sums (made for the same members and isovalue, over other points).
    // Throws data::Error(InvalidArgument) otherwise.
    void merge(const DistanceSums& other);
    // The sums of the members `keep` (indices, increasing) alone, as if only they had been
    // added: a member found to have no data after its points were added is left out this way.
    // Throws data::Error(InvalidArgument) for an index out of range.
    [[nodiscard]] DistanceSums subset(std::span<const std::size_t> keep) const;
    // The sums as one array of doubles, laid out alike for the same member count: adding two
    // such arrays element by element is merge(), so an MPI_SUM reduction of them combines ranks.
    [[nodiscard]] std::span<double> raw() { return m_sums; }
    [[nodiscard]] std::span<const double> raw() const { return m_sums; }

    // The distance matrix of the points added, as computeDistanceMatrix describes it. Throws
    // data::Error(AllValuesMissing) when no two members share a valid point.
    [[nodiscard]] DistanceMatrix finish() const;
    // The distance of the points added between members i and j (both < members()), +infinity
    // when they share no valid point.
    [[nodiscard]] double distance(std::size_t i, std::size_t j) const;

private:
    std::size_t m_members = 0;
    float m_isovalue = 0.0F;
    std::vector<double> m_sums;  // cross, squares, common (n x n each), then the point count
};

// Distances between all members at the given isovalue. A point counts for a pair when both
// members have a finite value there (NaN marks missing values; infinities are treated as
// missing too, since one would turn the whole sum into NaN). Two members that share no valid
// point cannot be compared: they are placed as far apart as the farthest pair that can be
// (d = the largest measured distance, so they merge last, at a finite height) and listed in
// pairsWithoutOverlap; the diagonal is always 0. Every distance is finite.
// Computed as matrix products over blocks of points, accumulated in double: the result agrees
// with a plain double loop over the points to about 1e-15 times the mean of s_i^2 + s_j^2
// (s = sqrt|f - mu|), since the expanded square cancels; nearly identical members get distances
// at that floor (never negative) rather than exactly 0.
// Throws data::Cancelled if stop is requested, data::Error(InvalidArgument) for an empty ensemble,
// a non-finite isovalue or a member whose value count differs from the grid's point count, and
// data::Error(AllValuesMissing) when no two members share a valid point (nothing to measure). The
// argument checks every distance of this measure needs (here and in member_summaries.h): throws
// data::Error(InvalidArgument) for an empty ensemble (`what` says what was being done), a
// non-finite isovalue, or a member whose value count differs from the grid's point count.
void checkDistanceArguments(const data::Ensemble& ensemble, float isovalue,
                            const std::string& what);

DistanceMatrix computeDistanceMatrix(const data::Ensemble& ensemble, float isovalue,
                                     const std::stop_token& stop = {},
                                     const data::Progress& progress = {});

// computeDistanceMatrix's matrix and, from the same pass over the points, every member's
// distance to `reference` (a field on the grid's points, such as the mean member): the
// distance above with the reference as member j, +infinity for a member that shares no valid
// point with it (as distancesToField gives it, member_summaries.h, to the rounding of the
// expanded square). The reference is one more column of the matrix products, so this costs a
// few percent more than the matrix alone instead of another pass over every member's values.
// Throws as computeDistanceMatrix, and data::Error(InvalidArgument) when the reference's value
// count differs from the grid's point count.
struct DistancesAndReference {
    DistanceMatrix matrix;
    std::vector<double> toReference;  // one per member
};
DistancesAndReference computeDistancesAndReference(const data::Ensemble& ensemble,
                                                   std::span<const float> reference, float isovalue,
                                                   const std::stop_token& stop = {},
                                                   const data::Progress& progress = {});

// What a user is told when some pairs share no valid point (empty when none): how many, the
// first few by member name, and the rule that placed them. One text for every command and the
// workbench.
std::string pairsWithoutOverlapWarning(const data::Ensemble& ensemble,
                                       const DistanceMatrix& distances);

}  // namespace ensil::prep

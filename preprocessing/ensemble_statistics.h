// Per-point statistics of an ensemble, or of any subset of its members (the selection, a
// cluster), for one isovalue c (METHODS.md section 17). At every grid point x, over the n(x)
// members with a finite value there (NaN and +-inf are missing): n, mean, sample standard
// deviation, minimum, maximum, range and the exceedance probability P(f > c); on every grid cell,
// the level-crossing probability: the share of the members whose cell straddles c.
// One streaming pass over the members with Welford's update in double, so members can come in
// any order and a reader can add each one as it is read (EnsembleStatisticsAccumulator): no
// second pass around the mean, and no loss of precision for large values such as geopotential.
// Pure functions; any thread. The accumulator is a plain value: one thread at a time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stop_token>
#include <vector>

#include "data/ensemble.h"
#include "data/job.h"

namespace ensil::prep {

struct EnsembleStatistics {
    float isovalue = 0.0F;             // c of the exceedance and level-crossing probabilities
    std::vector<std::size_t> members;  // the members summarised, in the order given
    // On the grid's points (index grid.index(i, j, k)):
    data::FieldValues count;       // n(x), the members with a finite value
    data::FieldValues mean;        // NaN where n = 0
    data::FieldValues stddev;      // sqrt(sum (f_i - mean)^2 / (n - 1)); NaN where n < 2
    data::FieldValues minimum;     // NaN where n = 0
    data::FieldValues maximum;     // NaN where n = 0
    data::FieldValues range;       // maximum - minimum; NaN where n = 0
    data::FieldValues exceedance;  // |{i : f_i > c}| / n; NaN where n = 0
    // On the cell grid, (nx - 1) x (ny - 1) x (nz - 1), index cellIndex(grid, i, j, k): the
    // share of the members with all 8 corners finite whose corners lie on both sides of c (some
    // > c, some <= c); NaN where no member has all 8.
    data::FieldValues levelCrossing;
};

// The cells of a grid (nx - 1) x (ny - 1) x (nz - 1), and the index of the cell whose lowest
// corner is point (i, j, k), x fastest like the points.
[[nodiscard]] inline std::size_t cellCount(const data::Grid& grid) {
    return grid.pointCount() == 0 ? 0 : (grid.nx() - 1) * (grid.ny() - 1) * (grid.nz() - 1);
}
[[nodiscard]] inline std::size_t cellIndex(const data::Grid& grid, std::size_t i, std::size_t j,
                                           std::size_t k) {
    return i + (grid.nx() - 1) * (j + (grid.ny() - 1) * k);
}

// The running sums behind EnsembleStatistics: per point Welford's count, mean and sum of
// squared deviations (double), minimum, maximum and the count above c; per cell the members
// with 8 finite corners and those among them that straddle c. Adding members in any order gives
// the same result up to rounding.
class EnsembleStatisticsAccumulator {
public:
    // Throws data::Error(InvalidArgument) for a non-finite isovalue or a grid without points.
    EnsembleStatisticsAccumulator(const data::Grid& grid, float isovalue);

    // Adds one member: grid.pointCount() values, x fastest. Throws data::Error(InvalidArgument)
    // when the count differs.
    void add(std::span<const float> member);
    // Adds the points of z level k of one member and the cells between levels k and k + 1 (none
    // for the top level). Adding every level of every member, in any order, is adding every
    // member; computeEnsembleStatistics goes level by level so that one level's sums stay in
    // cache while every member passes through them. Throws as add().
    void addLevel(std::span<const float> member, std::size_t k);
    // The same with the caller's scratch of grid.nx() * grid.ny() bytes: calls for different
    // levels touch disjoint sums, so they may run at once on threads of their own scratch.
    void addLevel(std::span<const float> member, std::size_t k, std::span<std::uint8_t> scratch);

    // The statistics of what was added so far (`members` left empty).
    [[nodiscard]] EnsembleStatistics result() const;

private:
    std::size_t m_nx, m_ny, m_nz;
    float m_isovalue;
    std::vector<std::uint32_t> m_count;      // per point: finite values
    std::vector<std::uint32_t> m_above;      // per point: finite values > c
    std::vector<double> m_mean;              // per point: Welford's running mean
    std::vector<double> m_squares;           // per point: Welford's M2, sum of squared deviations
    std::vector<float> m_minimum;            // per point; +inf until a value comes
    std::vector<float> m_maximum;            // per point; -inf until a value comes
    std::vector<std::uint32_t> m_cellValid;  // per cell: members with 8 finite corners
    std::vector<std::uint32_t> m_cellCrossing;  // per cell: those that straddle c
    std::vector<std::uint8_t> m_levelCodes;     // scratch: one level's corner codes
};

// The statistics over every member of the ensemble.
// Throws data::Cancelled if stop is requested (checked per level and member),
// data::Error(InvalidArgument) for an empty ensemble, a non-finite isovalue or a member whose
// value count differs from the grid's point count.
EnsembleStatistics computeEnsembleStatistics(const data::Ensemble& ensemble, float isovalue,
                                             const std::stop_token& stop = {},
                                             const data::Progress& progress = {});

// The statistics over the given members (indices into ensemble.members, in any order). An
// empty list is an error, not the whole ensemble: a selection of nothing has no statistics.
// Throws as above, and data::Error(InvalidArgument) for an empty list, an index out of range or
// an index given twice.
EnsembleStatistics computeEnsembleStatistics(const data::Ensemble& ensemble, float isovalue,
                                             std::span<const std::size_t> members,
                                             const std::stop_token& stop = {},
                                             const data::Progress& progress = {});

}  // namespace ensil::prep

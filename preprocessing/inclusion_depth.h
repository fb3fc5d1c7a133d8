// The contour boxplot in 3D (METHODS.md section 17): how central each member's isosurface is
// among the others, by the epsilon-inclusion depth of Chaves-de-Plaza et al. ("Inclusion Depth
// for Contour Ensembles", IEEE TVCG 2024), and from the depths the median member, the 50 % band
// and the outliers. A member's surface is the boundary of its inside set
// B_i = {grid points x : f_i(x) > c} (a missing value, NaN or +-inf, is never inside):
//   e(i in j) = 1 - |B_i \ B_j| / |B_i|      (1 when B_i is empty)
//   d_i = min( mean_{j != i} e(i in j), mean_{j != i} e(j in i) )
// A member whose inside set is empty has no surface and depth 0. A single member has depth 1
// (0 if its inside set is empty): there is nothing to compare it with.
// The authors' code averages over all N members, i itself included (e(i in i) = 1), which gives
// ((N - 1) d_i + 1) / N: an increasing affine map of d_i, so while every member has a surface
// the median, the band and the outliers are the same; only the values differ.
// The inside sets are packed 64 points to a word, so the N (N - 1) / 2 pairwise intersections
// cost N^2 m / 128 popcounts. Pure function; any thread.
#pragma once

#include <cstddef>
#include <span>
#include <stop_token>
#include <vector>

#include "data/ensemble.h"
#include "data/job.h"

namespace ensil::prep {

struct ContourBoxplot {
    float isovalue = 0.0F;
    std::vector<double> depth;              // d_i, one per member
    std::vector<std::size_t> insidePoints;  // |B_i|, one per member (0: no surface, depth 0)
    std::size_t median = 0;                 // the deepest member; of equals, the lowest index
    // The ceil(N / 2) deepest members, deepest first (of equals, the lower index first), so
    // bandMembers.front() == median. The band's bounding fields are their lowest and highest
    // values (band_envelope.h).
    std::vector<std::size_t> bandMembers;
    // Depths below lowerFence = Q1 - 1.5 (Q3 - Q1) of all N depths (Sun and Genton's rule for
    // functional boxplots; quartiles as in linearQuantile): the outliers, in index order.
    double lowerFence = 0.0;
    std::vector<std::size_t> outliers;
};

// The 50 % band's members from the depths: the ceil(N / 2) deepest, deepest first, equals in
// index order (so the first is the median). Empty for no depths.
std::vector<std::size_t> bandMembersOf(std::span<const double> depth);

// The q-quantile (0 <= q <= 1) of ascending values by linear interpolation between order
// statistics: position h = (n - 1) q, value v[floor h] + (h - floor h) (v[floor h + 1] -
// v[floor h]); numpy's default ("linear") method. Throws data::Error(InvalidArgument) for no
// values or q outside [0, 1].
double linearQuantile(std::span<const double> sorted, double q);

// Throws data::Cancelled if stop is requested (checked per member), data::Error(InvalidArgument)
// for an empty ensemble, a non-finite isovalue or a member whose value count differs from the
// grid's point count.
ContourBoxplot computeContourBoxplot(const data::Ensemble& ensemble, float isovalue,
                                     const std::stop_token& stop = {},
                                     const data::Progress& progress = {});

}  // namespace ensil::prep

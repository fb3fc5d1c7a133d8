// A copy of an ensemble at every s-th grid point, read slab by slab, for the workbench when the
// whole ensemble is larger than its memory budget (issue 20): the copy answers what needs the
// values at hand (statistics, histogram, floor, sections, the value under the cursor, previews)
// while the surfaces and distances come from the whole data read in slabs
// (preprocessing/streaming_preprocess.h). The first and last point of every axis are always
// kept, so the copy spans the same box as the data and every display mapping agrees. Pure
// functions; any thread.
#pragma once

#include <cstddef>
#include <stop_token>
#include <vector>

#include "data/ensemble.h"
#include "data/ensemble_reader.h"
#include "data/job.h"

namespace ensil::data {

// The indices 0, s, 2s, ... below n, and n - 1. n >= 2, s >= 1.
std::vector<std::size_t> thinnedIndices(std::size_t n, std::size_t stride);

// The grid at those indices along every axis (coordinates copied, so uneven spacing stays true).
Grid thinnedGrid(const Grid& grid, std::size_t stride);

// The least stride >= 2 whose copy of every member takes at most `budgetBytes`; 0 when even
// the copy of 2 points along every axis does not fit.
std::size_t thinningStrideFor(const EnsembleDescription& description, std::size_t budgetBytes);

// Reads the ensemble `description` says (describe()'s for `selection`) in `slabs` (every member,
// consecutive layers, covering the grid, as prep::planStreaming cuts it) and keeps every
// `stride`-th point: no more than one slab and the copy are in memory at once. Infinite values
// become NaN, as openEnsemble() does. Throws Error (UnsupportedFormat for a format that cannot
// read slabs, InvalidArgument for slabs that do not cover the grid), Cancelled.
Ensemble openThinnedEnsemble(const DataSelection& selection, const EnsembleDescription& description,
                             const std::vector<EnsemblePart>& slabs, std::size_t stride,
                             const std::stop_token& stop = {}, const Progress& progress = {});

}  // namespace ensil::data

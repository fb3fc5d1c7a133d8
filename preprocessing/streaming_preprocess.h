// Preprocessing an ensemble larger than memory (METHODS.md section 20): the ensemble is never
// held whole. Two passes over the files:
//   1. slabs of layers, every member at once (hyperslab reads, data/ensemble_part.h): the
//      moments (mean member, variance), the value range, each member's count of valid values
//      and the similarity's partial sums (DistanceSums), slab by slab;
//   2. members one at a time (a few in parallel, as the budget allows): each member read whole,
//      meshed, decimated, given its attributes from the moments of pass 1, packed; its
//      distance to the mean member.
// Every step sees the same numbers as the in-memory path (the moments are per point, the sums
// split over any partition of the points, each member's mesh is made from the whole member), so
// the results equal it: the meshes exactly, the distances to rounding (1e-12 relative). Both
// passes take lists of slabs and members, so MPI ranks can each take a share and merge.
// Pure functions; any thread.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <stop_token>
#include <string>
#include <vector>

#include "data/ensemble_reader.h"
#include "data/job.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/isosurface_pipeline.h"
#include "preprocessing/similarity.h"

namespace ensil::prep {

// How an ensemble is cut to fit a memory budget.
struct StreamingPlan {
    std::size_t memoryLimit = 0;            // bytes, as asked
    std::vector<data::EnsemblePart> slabs;  // every member, consecutive layers, covering the grid
    std::size_t membersAtOnce = 1;          // members meshed at the same time in pass 2
    // The bytes each part holds at most (estimates from the sizes; what the plan keeps within
    // the limit): the whole-grid results (moments), one slab with its temporaries, one member
    // being meshed.
    std::size_t resultBytes = 0, slabBytes = 0, memberBytes = 0;
    [[nodiscard]] std::size_t peakBytes() const {
        return resultBytes + std::max(slabBytes, membersAtOnce * memberBytes);
    }
};

// The plan for `description` within `memoryLimit` bytes, with at most `threads` members meshed
// at once (0: as many as oneTBB runs threads in this process). Slabs are as thick as the budget
// allows and as even as can be, at least 2 layers each (a grid's least; so with room for only 2
// layers and an odd count of them one slab has 3, a layer over the budget). Throws
// data::Error(OutOfMemory) saying the smallest limit that would do, when even 2 layers of every
// member or one member's meshing do not fit.
StreamingPlan planStreaming(const data::EnsembleDescription& description, std::size_t memoryLimit,
                            std::size_t threads);

// What pass 1 gives: sums over the slabs added so far. Merged over disjoint slabs (or ranks).
struct SlabSums {
    EnsembleMoments moments;          // whole grid; NaN in layers no slab has filled
    DistanceSums distances;           // every member, including those without data
    std::vector<double> validValues;  // per member (double: a sum an MPI reduction adds)
    double minimum = std::numeric_limits<double>::infinity();  // over the valid values
    double maximum = -std::numeric_limits<double>::infinity();
    double infiniteValues = 0;  // made missing, as openEnsemble does
};

// Empty sums for the ensemble `description` says, at the isovalue.
SlabSums emptySlabSums(const data::EnsembleDescription& description, float isovalue);

// Reads the slab (every member over its layers) and adds its moments, range and counts to
// `sums`; returns its distance sums, which the caller merges in slab order (DistanceSums::merge),
// so the total is the same bit for bit however the slabs are shared out (among MPI ranks too).
// Throws data::Error, Cancelled.
[[nodiscard]] DistanceSums addSlab(SlabSums& sums, const data::DataSelection& selection,
                                   const data::EnsembleDescription& description,
                                   const data::EnsemblePart& slab,
                                   const std::stop_token& stop = {});

// Pass 1 over every slab of `slabs` in order: the sums of the whole grid. `progress` runs from 0
// to 1 over the slabs. Throws data::Error, Cancelled.
SlabSums sumSlabs(const data::DataSelection& selection,
                  const data::EnsembleDescription& description,
                  const std::vector<data::EnsemblePart>& slabs, float isovalue,
                  const std::stop_token& stop = {}, const data::Progress& progress = {});

// `count` slabs of every member, covering the grid's layers in order, as even as can be and at
// least 2 layers each (fewer slabs when there are not 2 layers for each).
std::vector<data::EnsemblePart> evenSlabs(const data::EnsembleDescription& description,
                                          std::size_t count);

// One member's results from pass 2.
struct MemberResult {
    MeshedField meshed;
    double distanceToMean = 0.0;  // as distancesToField (member_summaries.h) gives it
};

// Reads member `member` (an index among the description's members) whole and meshes it as
// buildIsovalueMeshes would; its distance to the mean member as distancesToField gives it.
MemberResult meshMember(const data::DataSelection& selection,
                        const data::EnsembleDescription& description, std::size_t member,
                        const EnsembleMoments& moments, const AxisTables& axes,
                        const PipelineOptions& options, const std::stop_token& stop = {});

// Stands for the mean member in meshMembers' list.
inline constexpr std::size_t kMeanMember = static_cast<std::size_t>(-1);

// Pass 2 for the listed members (indices among the description's members, kMeanMember for the
// mean member, meshed from moments.mean without outlyingness), `atOnce` at a time, each thread
// holding one member at most. Results in list order. Throws data::Error, Cancelled.
std::vector<MemberResult> meshMembers(const data::DataSelection& selection,
                                      const data::EnsembleDescription& description,
                                      const std::vector<std::size_t>& members,
                                      const EnsembleMoments& moments, const AxisTables& axes,
                                      const PipelineOptions& options, std::size_t atOnce,
                                      const std::stop_token& stop = {},
                                      const data::Progress& progress = {});

// Pass 2 without the meshes (they were in the cache): each listed member (indices among the
// description's members) read whole, `atOnce` at a time, and its distance to the mean member as
// meshMember gives it. Throws data::Error, Cancelled.
std::vector<double> distancesToMeanOf(const data::DataSelection& selection,
                                      const data::EnsembleDescription& description,
                                      const std::vector<std::size_t>& members,
                                      const EnsembleMoments& moments, float isovalue,
                                      std::size_t atOnce, const std::stop_token& stop = {},
                                      const data::Progress& progress = {});

struct StreamedEnsemble {
    StreamingPlan plan;
    std::vector<std::size_t> membersWithoutData;  // indices among the description's members
    std::vector<std::string> memberNames;         // of the members kept, in order
    double minimum = 0.0, maximum = 0.0;          // the valid values' range
    double infiniteValues = 0;
    IsovalueMeshes meshes;                // the kept members' and the mean's
    DistanceMatrix distances;             // between the kept members
    std::vector<double> distancesToMean;  // per kept member
    double slabSeconds = 0.0, memberSeconds = 0.0;
    // Under MPI: the CPU seconds each rank spent on its own slabs and members (not waiting for
    // the others), by rank; their sum over their largest is the speed-up the split allows.
    std::vector<double> rankWorkSeconds;
};

// After pass 1 (sums over every slab): the members without data, the kept members' names,
// the range (given to checkRange) and the distances between the kept members, into `out`.
// Returns the kept members' indices. Throws data::Error(AllValuesMissing) when no member has
// data, and what checkRange throws.
using RangeCheck = std::function<void(double minimum, double maximum)>;
std::vector<std::size_t> concludeSlabs(const SlabSums& sums, const data::DataSelection& selection,
                                       const data::EnsembleDescription& description,
                                       const RangeCheck& checkRange, StreamedEnsemble& out);

// After pass 2: meshMembers' results for the kept members and, last, the mean, into `out`.
void collectMembers(StreamedEnsemble& out, std::vector<MemberResult>&& results, double wallSeconds);

// Called between the passes with the valid values' range, so a caller can refuse an isovalue
// outside it (by throwing) before any member is meshed.

// Both passes on one machine. Throws data::Error (AllValuesMissing when no member has data),
// data::Cancelled, and whatever `checkRange` throws.
StreamedEnsemble streamPreprocess(const data::DataSelection& selection,
                                  const data::EnsembleDescription& description,
                                  const StreamingPlan& plan, const PipelineOptions& options,
                                  float verticalExaggeration, const RangeCheck& checkRange = {},
                                  const std::stop_token& stop = {},
                                  const data::Progress& progress = {});

}  // namespace ensil::prep

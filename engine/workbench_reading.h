// How the workbench reads an ensemble, in memory or, when it is larger than the workbench's
// memory budget (issue 20), in slabs: then the workbench holds a thinned copy (every s-th grid
// point, data/thinned_ensemble.h) for what needs values at hand (statistics, histogram, floor,
// sections, the value under the cursor, the contour boxplot, previews) and builds each
// isovalue's surfaces, distances and clusters from the whole data read in slabs
// (engine/streamed_isovalue_job.h), as `ensil preprocess --memory-limit` does. Any thread.
#pragma once

#include <cstddef>
#include <optional>
#include <stop_token>
#include <string>

#include "data/ensemble.h"
#include "data/ensemble_reader.h"
#include "data/job.h"
#include "preprocessing/streaming_preprocess.h"

namespace ensil::engine {

// The whole data behind a thinned copy.
struct StreamedSource {
    data::DataSelection selection;
    data::EnsembleDescription description;  // of the whole data, from its headers
    std::size_t memoryLimit = 0;            // the workbench's budget, as given
    // The slab passes' plan, made once when the data are opened, within the budget less the
    // copy's share (its memoryLimit): every read and job of these data follows it.
    prep::StreamingPlan plan;
    std::size_t stride = 1;  // the copy keeps every stride-th point along each axis
};

struct WorkbenchEnsemble {
    data::Ensemble ensemble;  // the whole ensemble, or the thinned copy when `streamed`
    std::optional<StreamedSource> streamed;
    // The variables of the files that can be opened, by name (from the headers read anyway),
    // for the Ensemble panel's choice of another.
    std::vector<std::string> variables;
};

// The share of the budget the thinned copy may take with what the workbench builds from it (the
// in-memory peak of 1.5 times its values): a quarter; the slab passes take the rest.
inline constexpr double kThinnedCopyShare = 0.25;

// How the workbench reads `description`'s data within `memoryLimit`: nothing when whole (its
// in-memory peak, inMemoryPeakBytes, fits, or its format cannot be read in slabs, when
// openEnsemble's own check of the memory applies); otherwise the thinned copy's stride and the
// slab passes' share. Throws data::Error(OutOfMemory) when not even a copy at every few points
// and the slab passes fit, saying the budget that would do.
std::optional<StreamedSource> streamedSourceFor(const data::DataSelection& selection,
                                                const data::EnsembleDescription& description,
                                                std::size_t memoryLimit);

// Reads the selection whole when its in-memory peak (inMemoryPeakBytes) fits `memoryLimit` or
// its format cannot be read in slabs (then openEnsemble's own check of the memory applies);
// otherwise the thinned copy, read slab by slab. Throws data::Error (OutOfMemory, saying the
// budget that would do, when not even a copy at every few points and the slab passes fit;
// AllValuesMissing as openEnsemble), data::Cancelled.
WorkbenchEnsemble readForWorkbench(const data::DataSelection& selection, std::size_t memoryLimit,
                                   const std::stop_token& stop = {},
                                   const data::Progress& progress = {});

// What the Open dialog says of the data before they are read: "21 MiB of values" when they fit
// `memoryLimit` whole; "21 MiB of values, more than the memory budget of 16 MiB: read in slabs,
// a copy at every 2nd point in memory"; or why they cannot be opened within it (the
// OutOfMemory message). Never throws.
std::string howItOpens(const data::DataSelection& selection,
                       const data::EnsembleDescription& description, std::size_t memoryLimit);

// "every 2nd point", "every 3rd point": how a copy is thinned, in words.
std::string everyNthPoint(std::size_t stride);

// What the workbench says of a streamed ensemble: "'t' (3.40 GiB of values) is larger than the
// workbench's memory budget of 1.00 GiB: its surfaces, distances and clusters are built from
// the whole data, read in slabs; the statistics, histogram, floor, sections, contour boxplot
// and values under the cursor come from a copy at every 2nd point (210 MiB)."
std::string streamedDataNote(const StreamedSource& source, const data::Ensemble& copy);

}  // namespace ensil::engine

// The workbench's job for one isovalue of an ensemble larger than its memory budget
// (engine/workbench_reading.h): the members' and the mean's surfaces, the distance matrix
// and each member's distance to the mean from the whole data read in slabs and member by
// member (prep::streamPreprocess, the path of `ensil preprocess --memory-limit`, so the results
// equal the in-memory job's); the clustering from those distances; the contour boxplot, the
// P = 0.5 surface and P(f > c) for sections and the floor from the thinned copy in memory. The
// meshes go through the cache under the in-memory job's key: found there (from an earlier
// open, `ensil preprocess` or a cluster run), they are not made again, though the distances
// still take the slab pass and a read of every member. A pure function; any thread.
#pragma once

#include <stop_token>

#include "engine/isovalue_job.h"
#include "engine/workbench_reading.h"

namespace ensil::engine {

// `input.ensemble` and `input.moments` are the thinned copy's. Throws data::Error (also when
// the whole data's members with data are not the copy's: their names are given), Cancelled.
IsovalueOutcome runStreamedIsovalueJob(const IsovalueJobInput& input, const StreamedSource& source,
                                       const std::stop_token& stop = {},
                                       const data::Progress& progress = {});

}  // namespace ensil::engine

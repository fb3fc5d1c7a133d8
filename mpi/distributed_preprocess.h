// Streaming preprocessing (preprocessing/streaming_preprocess.h) spread over the ranks of an MPI
// job: rank r reads and sums the slabs r, r + K, r + 2K, ... (its own hyperslabs, serial netCDF
// per rank), the moments and counts are sum-reduced to every rank, each slab's distance sums are
// gathered to rank 0 and merged there in slab order (so any K gives the same sums bit for bit),
// then rank r meshes the members r, r + K, ... (and the mean member is the last field) and sends
// them to rank 0, which returns the whole result. See ARCHITECTURE.md, "On a cluster".
#pragma once

#include <optional>

#include "data/ensemble_reader.h"
#include "mpi/mpi_session.h"
#include "preprocessing/streaming_preprocess.h"

namespace ensil::mpi {

// The slabs an MPI run cuts: the plan's, or more (up to one per 2 layers, at most 16) so that
// ranks have slabs to share; the same for any number of ranks, so the results do not depend on
// it.
prep::StreamingPlan distributedPlan(const prep::StreamingPlan& plan,
                                    const data::EnsembleDescription& description);

// Every rank calls it with the same arguments. Rank 0 returns the result; the others return
// nothing. A step that fails on one rank throws there (the caller ends the job); the checks every
// rank makes alike (checkRange, no member with data) throw on every rank.
// Set ENSIL_MPI_TEST_FAIL_RANK=R to make rank R fail at its first slab (for the tests of the
// failure path).
std::optional<prep::StreamedEnsemble> distributedPreprocess(
    const Session& session, const data::DataSelection& selection,
    const data::EnsembleDescription& description, const prep::StreamingPlan& plan,
    const prep::PipelineOptions& options, float verticalExaggeration,
    const prep::RangeCheck& checkRange);

}  // namespace ensil::mpi

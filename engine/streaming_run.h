// `ensil preprocess` for an ensemble larger than its memory budget (issue 20): the same results
// as preprocessEnsemble (engine/preprocess_run.h) but the ensemble is read in slabs and
// member by member (preprocessing/streaming_preprocess.h), so peak memory stays within
// `--memory-limit`. The contour boxplot is not made this way. Any thread.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <stop_token>
#include <string>

#include "data/ensemble_reader.h"
#include "engine/preprocess_run.h"

namespace ensil::engine {

// The memory budget when none is given: three quarters of what the system has available now,
// the ceiling the in-memory reader keeps to (data::checkMemoryFor).
std::size_t defaultMemoryLimit();

// What the in-memory path holds at its peak for the ensemble: its values and half as much again
// (the moments, the distance blocks, meshes on their way; 1.47 times measured on the demo).
std::size_t inMemoryPeakBytes(const data::EnsembleDescription& description);

// "1GiB", "512 MiB", "2G", "800M", "64k", "1500000" (bytes); powers of 1024 for K, M, G, T with
// or without "iB" or "B". Empty with `problem` saying what is wrong, otherwise.
std::optional<std::size_t> parseMemorySize(const std::string& text, std::string& problem);

// The streamed run's stage seconds under the names the in-memory run gives them ("slabs",
// "members", "meshes", "decimation", "attributes").
void recordStreamedSeconds(std::map<std::string, double>& seconds,
                           const prep::StreamedEnsemble& streamed);

// True when the selection's format can be read in slabs (NetCDF).
bool canStream(const data::DataSelection& selection);

// Where the two passes run: here (the default), or spread over the ranks of an MPI job
// (mpi/distributed_preprocess.h, whose `run` returns nothing on the ranks but 0).
struct StreamBackend {
    std::function<prep::StreamingPlan(const prep::StreamingPlan&)> refinePlan;  // may be empty
    std::function<std::optional<prep::StreamedEnsemble>(
        const prep::StreamingPlan&, const prep::PipelineOptions&, const prep::RangeCheck&)>
        run;
    std::string where;  // said in the note: "on 4 MPI ranks"; empty for here
};

// preprocessStreaming with the passes run by `backend`; nothing where the backend gives
// nothing (the ranks but 0), which then store no cache and say nothing after the plan.
std::optional<PreprocessResult> preprocessStreamingWith(
    const data::DataSelection& selection, const data::EnsembleDescription& description,
    const PreprocessRequest& request, std::size_t memoryLimit, const PreprocessNotice& notice,
    const StreamBackend& backend, const std::stop_token& stop = {},
    const data::Progress& progress = {});

// Throws PreprocessRefused (exit status 2 without request.isovalue: the default isovalue needs
// every value at once), data::Error (OutOfMemory when even the least streaming plan does not
// fit), data::Cancelled.
PreprocessResult preprocessStreaming(const data::DataSelection& selection,
                                     const data::EnsembleDescription& description,
                                     const PreprocessRequest& request, std::size_t memoryLimit,
                                     const PreprocessNotice& notice,
                                     const std::stop_token& stop = {},
                                     const data::Progress& progress = {});

}  // namespace ensil::engine

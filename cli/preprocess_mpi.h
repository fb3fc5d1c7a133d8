// `mpirun -np K ensil preprocess FILE... --iso X [--memory-limit SIZE] [--cache-dir DIR]`: the
// command's work spread over the job's ranks (mpi/distributed_preprocess.h), built when OpenMPI
// was found (ENSIL_WITH_MPI). Every rank parses the same options and calls this; rank 0 prints
// the result and writes the cache, the others print nothing. A step that fails on one rank ends
// every rank with its message (MPI_Abort), so none waits forever.
#pragma once

#include <QString>
#include <QTextStream>
#include <cstddef>
#include <functional>
#include <optional>

#include "data/ensemble_reader.h"
#include "engine/preprocess_run.h"

namespace ensil::cli {

// True when this process is a rank of an MPI job and ensil was built with MPI.
bool runningUnderMpi();

// Returns the exit status. `print` is called on rank 0 with the result.
int runDistributedPreprocess(const data::DataSelection& selection,
                             const engine::PreprocessRequest& request,
                             std::optional<std::size_t> memoryLimit,
                             const std::function<void(engine::PreprocessResult&&)>& print,
                             QTextStream& err);

}  // namespace ensil::cli

// What a Python `ensil.PreprocessResult` holds: engine::preprocessEnsemble's result (shared with
// the meshes and sections made from it) and the linkage it was clustered with. Any thread.
#pragma once

#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>

#include "data/job.h"
#include "engine/preprocess_run.h"
#include "preprocessing/clustering.h"

namespace ensil::python {

struct PyEnsemble;

struct PyPreprocessResult {
    std::shared_ptr<const engine::PreprocessResult> result;
    prep::Linkage linkage;
};

// Runs `step` as runInterruptible does, gathering what the engine notices on its worker (the
// notices of engine::preprocessEnsemble and preprocessTimeSeries), then says each as an
// ensil.DataWarning ("warning: ..."), as the command line prints them. Called with the GIL held.
void runPreprocessing(const std::function<void(const std::stop_token&, const data::Progress&,
                                               const engine::PreprocessNotice&)>& step,
                      const pybind11::object& progress);

// Ensemble.preprocess's arguments as the engine's request (the command line's ranges and
// messages), shared by Ensemble.time_series. Raises ArgumentError for a value out of range.
engine::PreprocessRequest preprocessRequestOf(const PyEnsemble& self,
                                              const std::optional<double>& iso,
                                              const pybind11::object& clusters,
                                              const pybind11::object& linkage, double error,
                                              bool decimate, bool cache,
                                              const std::optional<std::string>& cacheDir);

}  // namespace ensil::python

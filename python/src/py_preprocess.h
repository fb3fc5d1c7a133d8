// What a Python `ensil.PreprocessResult` holds: engine::preprocessEnsemble's result (shared with
// the meshes and sections made from it) and the linkage it was clustered with. Any thread.
#pragma once

#include <memory>

#include "engine/preprocess_run.h"
#include "preprocessing/clustering.h"

namespace ensil::python {

struct PyPreprocessResult {
    std::shared_ptr<const engine::PreprocessResult> result;
    prep::Linkage linkage;
};

}  // namespace ensil::python

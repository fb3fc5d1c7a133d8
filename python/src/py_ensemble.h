// The ensemble a Python `ensil.Ensemble` holds: the data (shared, never changed once made) and
// where they came from, which says how to name them for the mesh cache and how to describe them
// for info(). Any thread.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "data/demo_ensemble.h"
#include "data/ensemble.h"
#include "data/ensemble_reader.h"

namespace ensil::python {

struct PyEnsemble {
    std::shared_ptr<const data::Ensemble> data;
    // Read from files: the selection and what the reader found (for info()).
    std::optional<data::DataSelection> selection;
    std::optional<data::EnsembleDescription> description;
    // The built-in demo.
    std::optional<data::DemoEnsembleParams> demo;

    // The data's identity for the mesh cache (the command line's and the workbench's, so they
    // share cached meshes); empty for arrays, which are not cached.
    [[nodiscard]] std::string sourceKey() const;
};

}  // namespace ensil::python

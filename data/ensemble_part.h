// Reading an ensemble in parts (slabs of layers, ranges of members) so that no more of it is in
// memory than the part: the streaming and MPI preprocessing read through these. The part is
// checked against the headers' description before any memory is asked for.
#pragma once

#include <cstddef>
#include <stop_token>

#include "data/ensemble.h"
#include "data/ensemble_reader.h"
#include "data/job.h"

namespace ensil::data {

// The grid's layers [firstLayer, firstLayer + layerCount) along z, axes x and y unchanged.
// Throws Error(InvalidArgument) when they leave the grid or are fewer than 2 (a grid needs 2
// points along every axis).
Grid gridLayers(const Grid& grid, std::size_t firstLayer, std::size_t layerCount);

// Throws Error(InvalidArgument), naming the data and variable, when `part` is empty, names
// members or layers beyond those `description` has, or has fewer than 2 layers.
void checkEnsemblePart(const EnsembleDescription& description, const EnsemblePart& part,
                       const std::string& source);

// Checks `part`, then reads it with the selection's reader (whose describe() gave
// `description`). Infinite values become NaN (missing), counted in Ensemble::infiniteValues, as
// openEnsemble() does. Unlike openEnsemble(), a part where every value is missing is returned
// as it is (a slab can lie wholly in a masked region). Throws Error(UnsupportedFormat) for a
// format whose reader cannot read parts, Error, Cancelled.
Ensemble openEnsemblePart(const DataSelection& selection, const EnsembleDescription& description,
                          const EnsemblePart& part, const std::stop_token& stop = {},
                          const Progress& progress = {});

}  // namespace ensil::data

#include "data/ensemble_part.h"

#include <cmath>
#include <limits>
#include <string>

#include "data/error.h"
#include "data/reader_support.h"

namespace ensil::data {

Ensemble EnsembleReader::readPart(const DataSelection& selection, const EnsembleDescription&,
                                  const EnsemblePart&, const std::stop_token&,
                                  const Progress&) const {
    throw Error(ErrorKind::UnsupportedFormat,
                "'" + sourceOf(selection.paths) + "': ensil cannot yet read " + name() +
                    " files in slabs; convert the data to NetCDF (ensil reads slabs of those) "
                    "or preprocess it in memory");
}

Grid gridLayers(const Grid& grid, std::size_t firstLayer, std::size_t layerCount) {
    const std::size_t nz = grid.nz();
    if (layerCount < 2 || firstLayer >= nz || layerCount > nz - firstLayer) {
        throw Error(ErrorKind::InvalidArgument, "layers " + std::to_string(firstLayer) + " to " +
                                                    std::to_string(firstLayer + layerCount) +
                                                    " (exclusive) of axis '" + grid.z().name +
                                                    "' are not 2 or more of its " +
                                                    std::to_string(nz) + " layers");
    }
    Axis z = grid.z();
    const auto first = z.values.begin() + static_cast<std::ptrdiff_t>(firstLayer);
    z.values.assign(first, first + static_cast<std::ptrdiff_t>(layerCount));
    return {grid.x(), grid.y(), std::move(z)};
}

void checkEnsemblePart(const EnsembleDescription& description, const EnsemblePart& part,
                       const std::string& source) {
    const std::string what = "'" + description.variable + "' in " + source;
    if (part.memberCount == 0 || part.firstMember >= description.members ||
        part.memberCount > description.members - part.firstMember) {
        throw Error(ErrorKind::InvalidArgument,
                    "cannot read members " + std::to_string(part.firstMember) + " to " +
                        std::to_string(part.firstMember + part.memberCount) + " (exclusive) of " +
                        what + ", which has " + std::to_string(description.members) + " members");
    }
    try {
        const Grid layers = gridLayers(description.grid, part.firstLayer, part.layerCount);
        if (part.window) (void)gridWindow(layers, *part.window);
    } catch (const Error& e) {
        throw Error(ErrorKind::InvalidArgument, "cannot read a slab of " + what + ": " + e.what());
    }
}

Ensemble openEnsemblePart(const DataSelection& selection, const EnsembleDescription& description,
                          const EnsemblePart& part, const std::stop_token& stop,
                          const Progress& progress) {
    const EnsembleReader& reader = readerFor(selection);
    checkEnsemblePart(description, part, sourceOf(selection.paths));
    // A part of the levels the selection keeps is a part of the file's levels further up, and
    // of the file's columns and rows in the region kept.
    Ensemble ensemble = reader.readPart(selection, fileDescription(description),
                                        filePart(description, part), stop, progress);
    makeInfinitiesMissing(ensemble);
    return ensemble;
}

}  // namespace ensil::data

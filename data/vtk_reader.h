// Reads ensembles from VTK image files with VTK's own readers: legacy .vtk files holding
// STRUCTURED_POINTS or RECTILINEAR_GRID, and XML ImageData (.vti) files. One file per member (a
// single file is a one-member ensemble), every file on the same grid; members are named after
// the file stems. DataSelection::variable names a point-data array; left empty, the reader takes
// the first scalar (1-component) array. Any numeric type is converted to float. Image data gets
// uniform axes from its origin and spacing, a rectilinear grid its coordinate arrays (axes x, y,
// z, no units). VTK's messages are collected per reader and turned into data::Error, so a
// failed read prints nothing on stderr. Stateless; callable from any thread (each call builds
// its own VTK readers).
#pragma once

#include "data/ensemble_reader.h"

namespace ensil::data {

class VtkReader final : public EnsembleReader {
public:
    [[nodiscard]] std::string name() const override { return "VTK"; }
    // Legacy files start with "# vtk DataFile"; XML ones with "<?xml" or "<VTKFile" and name
    // ImageData within their first 512 bytes.
    [[nodiscard]] bool recognizes(const std::string& path) const override;
    [[nodiscard]] EnsembleDescription describe(const DataSelection& selection) const override;
    [[nodiscard]] Ensemble read(const DataSelection& selection, const std::stop_token& stop,
                                const Progress& progress) const override;
};

}  // namespace ensil::data

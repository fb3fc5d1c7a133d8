// The structure of a legacy VTK file (.vtk) read without its values: dataset type, grid
// (dimensions with origin and spacing, or a rectilinear grid's coordinates) and the name, type
// and component count of every point-data array. VTK's legacy reader can neither list arrays
// without reading them nor notice a truncated file (it warns on stderr and keeps the garbage),
// so VtkReader scans each file with this first. Pure function; callable from any thread.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace ensil::data::vtk {

struct LegacyArray {
    std::string name;
    std::string type;  // as written in the file, lower case: "float", "unsigned_char" ...
    std::size_t components = 1;
};

struct LegacyStructure {
    bool binary = false;
    std::string dataset;  // upper case: "STRUCTURED_POINTS", "RECTILINEAR_GRID", "POLYDATA" ...
    std::array<std::size_t, 3> dimensions{};  // x, y, z
    std::array<double, 3> origin{0.0, 0.0, 0.0};
    std::array<double, 3> spacing{1.0, 1.0, 1.0};
    std::array<std::vector<double>, 3> coordinates;  // RECTILINEAR_GRID only
    std::vector<LegacyArray> pointArrays;
};

// Scans the whole file: binary values are skipped by their size, text values token by token.
// Stops after the DATASET line for dataset types other than STRUCTURED_POINTS and
// RECTILINEAR_GRID. Throws Error(CorruptFile) naming the file and what is missing for a
// truncated or malformed file, Error(UnsupportedFormat) for string arrays (which cannot be
// skipped without parsing them).
LegacyStructure scanLegacyFile(const std::string& path);

}  // namespace ensil::data::vtk

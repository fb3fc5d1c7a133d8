// The versions of the libraries the data layer reads and writes files with, as this process
// runs them (not as it was compiled against): what `ensil --version` prints for bug reports.
#pragma once

#include <string>
#include <vector>

namespace ensil::data {

struct LibraryVersion {
    std::string name;     // "netCDF"
    std::string version;  // "4.9.0"
};

// netCDF, HDF5, ecCodes, PROJ, VTK and xxHash, in that order.
std::vector<LibraryVersion> readerLibraryVersions();

}  // namespace ensil::data

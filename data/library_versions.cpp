#include "data/library_versions.h"

#include <H5public.h>
#include <eccodes.h>
#include <netcdf.h>
#include <proj.h>
#include <vtkVersion.h>
#include <xxhash.h>

#include <string_view>

namespace ensil::data {
namespace {
// "1.2.3" from a number written as major * 10000 + minor * 100 + patch (ecCodes, xxHash).
std::string dottedVersion(long number) {
    return std::to_string(number / 10000) + "." + std::to_string(number / 100 % 100) + "." +
           std::to_string(number % 100);
}
}  // namespace

std::vector<LibraryVersion> readerLibraryVersions() {
    std::vector<LibraryVersion> versions;
    // nc_inq_libvers(): "4.9.0 of Jan  3 2023 ..."; the version is its first word.
    const std::string_view netcdf = nc_inq_libvers();
    versions.push_back({"netCDF", std::string(netcdf.substr(0, netcdf.find(' ')))});
    unsigned major = 0, minor = 0, release = 0;
    H5get_libversion(&major, &minor, &release);
    versions.push_back({"HDF5", std::to_string(major) + "." + std::to_string(minor) + "." +
                                    std::to_string(release)});
    versions.push_back({"ecCodes", dottedVersion(codes_get_api_version())});
    versions.push_back({"PROJ", proj_info().version});
    versions.push_back({"VTK", vtkVersion::GetVTKVersion()});
    versions.push_back({"xxHash", dottedVersion(static_cast<long>(XXH_versionNumber()))});
    return versions;
}

}  // namespace ensil::data

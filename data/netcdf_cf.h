// Writing CF-1.8 NetCDF files: what the ensemble writer (data/netcdf_writer.cpp) and the
// statistics writer (data/statistics_writer.cpp) share. A file being written, its text and
// float attributes, a grid axis as a dimension with its coordinate variable, and the rule that
// a failed write leaves no partial file. Internal to data/ (netcdf.h stays out of headers).
// One file per thread; writeCfFile holds netcdfLibraryMutex() while it writes.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>

#include "data/grid.h"

namespace ensil::data {

// A NetCDF-4 file opened for writing (created, replacing any file of that name).
class NetcdfOutput {
public:
    // Throws Error(WriteFailed) naming the path and the library's reason.
    explicit NetcdfOutput(std::string path);
    NetcdfOutput(const NetcdfOutput&) = delete;
    NetcdfOutput& operator=(const NetcdfOutput&) = delete;
    ~NetcdfOutput();

    // Finishes the file. Throws Error(WriteFailed).
    void close();
    // Gives up on the file without finishing it (used before removing a partial file).
    void abort();
    [[nodiscard]] int id() const { return m_id; }
    [[nodiscard]] const std::string& path() const { return m_path; }

    // Throws Error(WriteFailed) "cannot <what> in '<path>': <reason>" unless status is NC_NOERR.
    void check(int status, const std::string& what) const;
    // A text attribute of variable `var` (NC_GLOBAL for the file); nothing when value is empty.
    void text(int var, const char* name, const std::string& value) const;
    // A float attribute, e.g. _FillValue = NaN.
    void floatAttribute(int var, const char* name, float value) const;
    // A double attribute of one or more values (a grid mapping's parameters).
    void doubleAttribute(int var, const char* name, std::span<const double> values) const;

private:
    std::string m_path;
    int m_id = -1;
};

// A dimension and its coordinate variable, as the writers define them.
struct CfCoordinate {
    int dimension = -1;
    int variable = -1;
};

// "X", "Y", "Z" for grid axis 0, 1, 2.
const char* cfAxisLetter(int axis);

// Defines dimension `name` of `size` points and its double coordinate variable with the
// grid axis `axis`'s (0 x, 1 y, 2 z) units, standard_name, long_name (`longName`, or the
// standard name, or the axis name), axis letter and, for z, positive up or down.
CfCoordinate defineCfCoordinate(const NetcdfOutput& nc, const Axis& axis, int axisIndex,
                                const std::string& name, std::size_t size,
                                const std::string& longName = {});

// Creates `path`, lets `body` define and write everything, and finishes the file, holding
// netcdfLibraryMutex() throughout. When anything throws, the partial file is removed and the
// exception passes on: no truncated file is left behind.
void writeCfFile(const std::string& path, const std::function<void(const NetcdfOutput&)>& body);

}  // namespace ensil::data

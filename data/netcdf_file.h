// A thin RAII wrapper over a netCDF-C file handle opened for reading, with the queries the
// reader needs (dimensions, variables, attributes) and errors that name the file. Internal to
// data/ (netcdf.h stays out of public headers). One instance per thread: netCDF-C is not
// thread-safe, so callers must not share a handle and the reader serialises library calls.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace ensil::data {

// netCDF-C (and HDF5 beneath it) is not thread-safe; every call into the library holds this.
std::mutex& netcdfLibraryMutex();

struct NcDimension {
    int id = -1;
    std::string name;
    std::size_t size = 0;
};

struct NcVariable {
    int id = -1;
    std::string name;
    int type = 0;             // nc_type
    std::vector<int> dimIds;  // in storage order
};

class NetcdfFile {
public:
    // Throws Error(FileNotFound / UnsupportedFormat / CorruptFile) naming the path.
    explicit NetcdfFile(std::string path);
    NetcdfFile(const NetcdfFile&) = delete;
    NetcdfFile& operator=(const NetcdfFile&) = delete;
    ~NetcdfFile();

    [[nodiscard]] const std::string& path() const { return m_path; }
    [[nodiscard]] int id() const { return m_id; }
    [[nodiscard]] std::string formatName() const;  // "NetCDF-4", "NetCDF classic", ...

    [[nodiscard]] const std::vector<NcDimension>& dimensions() const { return m_dims; }
    [[nodiscard]] const std::vector<NcVariable>& variables() const { return m_vars; }
    [[nodiscard]] const NcDimension& dimension(int id) const;
    [[nodiscard]] const NcDimension* findDimension(const std::string& name) const;
    [[nodiscard]] const NcVariable* findVariable(const std::string& name) const;
    // The coordinate variable of a dimension: a 1D variable of the same name over it.
    [[nodiscard]] const NcVariable* coordinateVariable(const NcDimension& dim) const;

    [[nodiscard]] std::optional<std::string> textAttribute(int varId, const char* name) const;
    [[nodiscard]] std::vector<double> numericAttribute(int varId, const char* name) const;
    [[nodiscard]] int attributeType(int varId, const char* name) const;  // 0 when absent
    // The names of a variable's attributes (NC_GLOBAL for the file's), in file order.
    [[nodiscard]] std::vector<std::string> attributeNames(int varId) const;
    [[nodiscard]] std::string text(int varId, const char* name) const {
        return textAttribute(varId, name).value_or("");
    }

    // Values of a 1D variable as doubles. Throws Error(CorruptFile).
    [[nodiscard]] std::vector<double> readDoubles(const NcVariable& var) const;
    // The rows of a 2D character variable (n, length) as strings, trailing blanks and NULs
    // dropped: WRF's Times(Time, DateStrLen). Throws Error(CorruptFile), and
    // Error(InvalidArgument) for a variable of another type or shape, or of more than 16 MiB.
    [[nodiscard]] std::vector<std::string> readStrings(const NcVariable& var) const;
    // Values of the hyperslab start .. start + count of a variable as doubles. Throws
    // Error(CorruptFile).
    [[nodiscard]] std::vector<double> readDoubles(const NcVariable& var,
                                                  const std::vector<std::size_t>& start,
                                                  const std::vector<std::size_t>& count) const;

    // The bytes a netCDF-4 variable's values take in the file (HDF5's storage size): 0 when no
    // chunk was ever written, so that every value would read as the fill value. nullopt for the
    // classic formats, whose variables always have their bytes (or the file is truncated), and
    // when HDF5 cannot tell.
    [[nodiscard]] std::optional<std::uint64_t> storedBytes(const NcVariable& var) const;

    // Throws Error(CorruptFile) with the library's reason when status is not NC_NOERR.
    void check(int status, const std::string& what) const;

private:
    std::string m_path;
    int m_id = -1;
    std::vector<NcDimension> m_dims;
    std::vector<NcVariable> m_vars;
};

// Whether an HDF5 file was written as netCDF-4: the root group has _NCProperties (netCDF-C 4.4.1
// and later) or _nc3_strict (the classic model), or a dataset has dimension scales (how netCDF-4
// keeps its dimensions; older files have only those). Plain HDF5 files, as h5py writes them,
// have none. False when HDF5 cannot open the file. Hold netcdfLibraryMutex() around the call.
bool hasNetcdf4Marks(const std::string& path);

// "(number, time, plev, lat, lon)"
std::string describeDimensions(const NetcdfFile& file, const NcVariable& var);

}  // namespace ensil::data

#include "data/netcdf_file.h"

#include <hdf5.h>
#include <netcdf.h>

#include <array>
#include <filesystem>

#include "data/error.h"

namespace ensil::data {

std::mutex& netcdfLibraryMutex() {
    static std::mutex mutex;
    return mutex;
}

namespace {
// netCDF-4 files are read through HDF5, whose error printing is per thread in a thread-safe
// build: netCDF turns it off only on the thread that first used the library, so reading on a
// worker printed pages of HDF5-DIAG for attributes netCDF merely probes for. netCDF reports
// every error through its status codes; HDF5's own printing stays off on threads that read.
void quietHdf5OnThisThread() {
    thread_local bool quiet = false;
    if (quiet) return;
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    quiet = true;
}
}  // namespace

NetcdfFile::NetcdfFile(std::string path) : m_path(std::move(path)) {
    if (!std::filesystem::exists(m_path)) {
        throw Error(ErrorKind::FileNotFound, "no such file: '" + m_path + "'");
    }
    quietHdf5OnThisThread();
    const int status = nc_open(m_path.c_str(), NC_NOWRITE, &m_id);
    if (status == NC_ENOTNC) {
        throw Error(ErrorKind::UnsupportedFormat,
                    "'" + m_path + "' is not a NetCDF file (or it is truncated)");
    }
    if (status != NC_NOERR) {
        m_id = -1;
        throw Error(ErrorKind::CorruptFile, "cannot open '" + m_path +
                                                "' as NetCDF: " + nc_strerror(status) +
                                                "; the file may be truncated or damaged");
    }
    int ndims = 0, nvars = 0;
    check(nc_inq(m_id, &ndims, &nvars, nullptr, nullptr), "read the header");
    std::array<char, NC_MAX_NAME + 1> name{};
    // Dimension ids are 0..ndims-1 in classic files; netCDF-4 groups aside, the root's are too.
    std::vector<int> dimIds(static_cast<std::size_t>(ndims));
    check(nc_inq_dimids(m_id, &ndims, dimIds.data(), 0), "list dimensions");
    for (int id : dimIds) {
        std::size_t size = 0;
        check(nc_inq_dim(m_id, id, name.data(), &size), "read a dimension");
        m_dims.push_back({id, name.data(), size});
    }
    for (int v = 0; v < nvars; ++v) {
        NcVariable var;
        var.id = v;
        int type = 0, nd = 0;
        std::array<int, NC_MAX_VAR_DIMS> ids{};
        check(nc_inq_var(m_id, v, name.data(), &type, &nd, ids.data(), nullptr), "read a variable");
        var.name = name.data();
        var.type = type;
        var.dimIds.assign(ids.begin(), ids.begin() + nd);
        m_vars.push_back(std::move(var));
    }
    checkNotTruncated();
}

void NetcdfFile::checkNotTruncated() const {
    // netCDF-C reads past the end of a truncated classic file as zeros (such files may
    // legitimately be short when written without fill), so a cut download would load silently.
    // The data alone needs at least this many bytes; the header comes on top.
    int format = 0;
    nc_inq_format(m_id, &format);
    if (format == NC_FORMAT_NETCDF4 || format == NC_FORMAT_NETCDF4_CLASSIC) return;  // HDF5 checks
    std::uintmax_t needed = 0;
    for (const NcVariable& var : m_vars) {
        std::size_t typeSize = 0;
        nc_inq_type(m_id, var.type, nullptr, &typeSize);
        std::uintmax_t bytes = typeSize;
        for (int d : var.dimIds) bytes *= dimension(d).size;
        needed += bytes;
    }
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(m_path, error);
    if (!error && size < needed) {
        throw Error(ErrorKind::CorruptFile,
                    "'" + m_path + "' is truncated: it holds " + std::to_string(size) +
                        " bytes, but its header describes at least " + std::to_string(needed) +
                        " bytes of data. Copy or download it again");
    }
}

NetcdfFile::~NetcdfFile() {
    if (m_id >= 0) nc_close(m_id);
}

std::string NetcdfFile::formatName() const {
    int format = 0;
    nc_inq_format(m_id, &format);
    switch (format) {
        case NC_FORMAT_NETCDF4:
            return "NetCDF-4";
        case NC_FORMAT_NETCDF4_CLASSIC:
            return "NetCDF-4 classic model";
        case NC_FORMAT_64BIT_OFFSET:
            return "NetCDF 64-bit offset";
        case NC_FORMAT_CDF5:
            return "NetCDF CDF-5";
        default:
            return "NetCDF classic";
    }
}

void NetcdfFile::check(int status, const std::string& what) const {
    if (status != NC_NOERR) {
        throw Error(ErrorKind::CorruptFile, "cannot " + what + " in '" + m_path +
                                                "': " + nc_strerror(status) +
                                                "; the file may be truncated or damaged");
    }
}

const NcDimension& NetcdfFile::dimension(int id) const {
    for (const NcDimension& d : m_dims) {
        if (d.id == id) return d;
    }
    throw Error(ErrorKind::CorruptFile, "'" + m_path + "' refers to a dimension it lacks");
}

const NcDimension* NetcdfFile::findDimension(const std::string& name) const {
    for (const NcDimension& d : m_dims) {
        if (d.name == name) return &d;
    }
    return nullptr;
}

const NcVariable* NetcdfFile::findVariable(const std::string& name) const {
    for (const NcVariable& v : m_vars) {
        if (v.name == name) return &v;
    }
    return nullptr;
}

const NcVariable* NetcdfFile::coordinateVariable(const NcDimension& dim) const {
    const NcVariable* v = findVariable(dim.name);
    return v != nullptr && v->dimIds.size() == 1 && v->dimIds[0] == dim.id ? v : nullptr;
}

std::optional<std::string> NetcdfFile::textAttribute(int varId, const char* name) const {
    nc_type type = 0;
    std::size_t length = 0;
    if (nc_inq_att(m_id, varId, name, &type, &length) != NC_NOERR || type != NC_CHAR) {
        return std::nullopt;
    }
    std::string value(length, '\0');
    if (nc_get_att_text(m_id, varId, name, value.data()) != NC_NOERR) return std::nullopt;
    while (!value.empty() && value.back() == '\0') value.pop_back();
    return value;
}

std::vector<double> NetcdfFile::numericAttribute(int varId, const char* name) const {
    nc_type type = 0;
    std::size_t length = 0;
    if (nc_inq_att(m_id, varId, name, &type, &length) != NC_NOERR || type == NC_CHAR ||
        type == NC_STRING || length == 0) {
        return {};
    }
    std::vector<double> values(length);
    if (nc_get_att_double(m_id, varId, name, values.data()) != NC_NOERR) return {};
    return values;
}

std::vector<std::string> NetcdfFile::attributeNames(int varId) const {
    int count = 0;
    if (nc_inq_varnatts(m_id, varId, &count) != NC_NOERR || count < 0) return {};
    std::vector<std::string> names;
    std::array<char, NC_MAX_NAME + 1> name{};
    for (int a = 0; a < count; ++a) {
        if (nc_inq_attname(m_id, varId, a, name.data()) == NC_NOERR)
            names.emplace_back(name.data());
    }
    return names;
}

int NetcdfFile::attributeType(int varId, const char* name) const {
    nc_type type = 0;
    return nc_inq_atttype(m_id, varId, name, &type) == NC_NOERR ? type : 0;
}

std::vector<double> NetcdfFile::readDoubles(const NcVariable& var) const {
    std::size_t n = 1;
    for (int d : var.dimIds) n *= dimension(d).size;
    std::vector<double> values(n);
    check(nc_get_var_double(m_id, var.id, values.data()), "read variable '" + var.name + "'");
    return values;
}

std::string describeDimensions(const NetcdfFile& file, const NcVariable& var) {
    std::string text = "(";
    for (std::size_t i = 0; i < var.dimIds.size(); ++i) {
        if (i > 0) text += ", ";
        text += file.dimension(var.dimIds[i]).name;
    }
    return text + ")";
}

}  // namespace ensil::data

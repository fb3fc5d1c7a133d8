#include "data/netcdf_file.h"

#include <hdf5.h>
#include <netcdf.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

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

// netCDF-C believes the counts in a classic header (CDF-1, CDF-2, CDF-5): a 150-byte file
// declaring two billion variables made nc_open ask for 15 GB, and names longer than
// NC_MAX_NAME or more than NC_MAX_VAR_DIMS dimensions of a variable were copied past the ends
// of the NC_MAX_* buffers the library's API asks callers for. So the header is walked here
// before nc_open, as the format specification lays it out: every count must fit in the bytes
// left in the file, every name in NC_MAX_NAME bytes and every variable's dimensions in
// NC_MAX_VAR_DIMS, and every list tag and type must be one the format has (netCDF-C only
// asserts the types, so a damaged one made it read on out of step, taking later bytes for
// counts). A header that ends early is left to nc_open, which refuses it.
// A file cut inside its data has a whole header, and netCDF-C reads the values past its end as
// zeros (or the fill value): so once the header is read, the size it implies (where each
// variable's values begin, plus their size; for record variables, the records before the last
// times the record size, plus the last one's values) is checked against the file's size before
// any value is read. The values' sizes come from the dimensions and types, not from the header's
// vsize (which CDF-2 caps at 4 GiB), and without the padding after the last value, which a
// writer need not write.
class ClassicHeader {
public:
    ClassicHeader(const std::string& path, std::uintmax_t size)
        : m_path(path), m_in(path, std::ios::binary), m_size(size) {}

    void walk() {
        try {
            const std::string magic = bytes(4);
            m_cdf5 = magic[3] == 5;
            m_offsets = magic[3] == 1 ? 4 : 8;
            m_records = count();
            list(kDimensions, "dimensions", [this] {
                name("a dimension name");
                m_dimensions.push_back(count());  // the length; 0 for the record dimension
            });
            list(kAttributes, "global attributes", [this] { attribute("global"); });
            list(kVariables, "variables", [this] { variable(); });
        } catch (const EndOfFile&) {
            return;  // nc_open says what is wrong.
        }
        checkSize();
    }

private:
    struct EndOfFile {};
    struct Variable {
        std::string name;
        std::uint64_t begin = 0;  // where its values (its first record's) begin
        std::uint64_t bytes = 0;  // its values (one record's), unpadded
        bool record = false;
        bool known = true;  // false when a dimension id is not the file's: nc_open refuses it
    };
    static constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
    // Sizes a damaged header gives can overflow: they stop at the largest number instead.
    static std::uint64_t times(std::uint64_t a, std::uint64_t b) {
        return b != 0 && a > kMax / b ? kMax : a * b;
    }
    static std::uint64_t plus(std::uint64_t a, std::uint64_t b) {
        return a > kMax - b ? kMax : a + b;
    }
    // The list tags (netCDF-C keeps them in its private headers).
    static constexpr std::uint64_t kDimensions = 0x0A, kVariables = 0x0B, kAttributes = 0x0C;

    // Bytes per value of a type; CDF-1 and CDF-2 have the six classic types only.
    std::uint64_t typeSize(std::uint64_t type, const std::string& what) const {
        if (type == NC_BYTE || type == NC_CHAR) return 1;
        if (type == NC_SHORT) return 2;
        if (type == NC_INT || type == NC_FLOAT) return 4;
        if (type == NC_DOUBLE) return 8;
        if (m_cdf5 && type == NC_UBYTE) return 1;
        if (m_cdf5 && type == NC_USHORT) return 2;
        if (m_cdf5 && type == NC_UINT) return 4;
        if (m_cdf5 && (type == NC_INT64 || type == NC_UINT64)) return 8;
        fail("gives " + what + " the type " + std::to_string(type) +
             ", which is none of its format's");
    }

    [[noreturn]] void fail(const std::string& what) const {
        throw Error(ErrorKind::CorruptFile,
                    "'" + m_path + "' is damaged: its NetCDF header " + what);
    }
    [[nodiscard]] std::uintmax_t left() {
        const auto at = static_cast<std::uintmax_t>(m_in.tellg());
        return at < m_size ? m_size - at : 0;
    }
    std::string bytes(std::uint64_t n) {
        std::string text(static_cast<std::size_t>(n), '\0');
        if (!m_in.read(text.data(), static_cast<std::streamsize>(n))) throw EndOfFile{};
        return text;
    }
    std::uint64_t bigEndian(int n) {
        std::uint64_t value = 0;
        for (const char c : bytes(static_cast<std::uint64_t>(n))) {
            value = value << 8 | static_cast<unsigned char>(c);
        }
        return value;
    }
    std::uint64_t count() { return bigEndian(m_cdf5 ? 8 : 4); }
    // Names and values take a multiple of 4 bytes.
    static std::uint64_t padded(std::uint64_t n) { return (n + 3) / 4 * 4; }
    void skip(std::uint64_t n) {
        if (n > left()) throw EndOfFile{};
        m_in.seekg(static_cast<std::streamoff>(n), std::ios::cur);
    }
    // `n` items of at least `each` bytes must fit in what is left of the file.
    void require(std::uint64_t n, std::uint64_t each, const std::string& what) {
        if (n > left() / each) {
            fail("declares " + std::to_string(n) + " " + what + ", more than the file's " +
                 std::to_string(m_size) + " bytes can hold");
        }
    }
    std::string name(const std::string& what) {
        const std::uint64_t n = count();
        if (n > NC_MAX_NAME) {
            fail("gives " + what + " of " + std::to_string(n) + " bytes (NetCDF allows at most " +
                 std::to_string(NC_MAX_NAME) + ")");
        }
        std::string text = bytes(n);
        skip(padded(n) - n);
        return text;
    }
    // A list is ABSENT (two zeros) or its tag, its count and the items; each takes 8 bytes or
    // more, so the count bounds what netCDF-C allocates for it.
    template <typename Item>
    void list(std::uint64_t tag, const std::string& what, Item item) {
        const std::uint64_t found = bigEndian(4);
        const std::uint64_t n = count();
        if (found == 0 && n == 0) return;
        if (found != tag) {
            fail("has the tag " + std::to_string(found) + " where its list of " + what +
                 " should be");
        }
        require(n, 8, what);
        for (std::uint64_t i = 0; i < n; ++i) item();
    }
    void attribute(const std::string& owner) {
        const std::string attribute = name("an attribute name");
        const std::string what = owner + " attribute '" + attribute + "'";
        const std::uint64_t size = typeSize(bigEndian(4), what);
        const std::uint64_t n = count();
        require(n, size, "values for " + what);
        skip(padded(n * size));
    }
    void variable() {
        const std::string variable = name("a variable name");
        const std::uint64_t dims = count();
        if (dims > NC_MAX_VAR_DIMS) {
            fail("gives variable '" + variable + "' " + std::to_string(dims) +
                 " dimensions (NetCDF allows at most " + std::to_string(NC_MAX_VAR_DIMS) + ")");
        }
        Variable v;
        v.name = variable;
        std::uint64_t values = 1;
        for (std::uint64_t d = 0; d < dims; ++d) {
            const std::uint64_t id = count();
            if (id >= m_dimensions.size()) {
                v.known = false;
            } else if (m_dimensions[id] == 0) {
                v.record = v.record || d == 0;  // elsewhere nc_open refuses it
            } else {
                values = times(values, m_dimensions[id]);
            }
        }
        list(kAttributes, "attributes of variable '" + variable + "'",
             [&] { attribute("variable '" + variable + "'"); });
        v.bytes = times(values, typeSize(bigEndian(4), "variable '" + variable + "'"));
        count();                         // vsize
        v.begin = bigEndian(m_offsets);  // where its values begin
        m_variables.push_back(std::move(v));
    }

    // The size the header implies, against the file's; throws Error(CorruptFile) when the file
    // is shorter.
    void checkSize() const {
        // A streaming file's record count is unknown (all bits set); netCDF-C counts its
        // records from the file's size.
        const bool streaming = m_records == (m_cdf5 ? kMax : 0xFFFFFFFFU);
        std::uint64_t recordSize = 0;
        std::size_t recordVariables = 0;
        for (const Variable& v : m_variables) {
            if (!v.known) return;  // nc_open refuses the file
            if (v.record) {
                recordSize = plus(recordSize, padded(v.bytes));
                ++recordVariables;
            }
        }
        // One record variable alone is not padded (the format's special case).
        if (recordVariables == 1) {
            for (const Variable& v : m_variables) {
                if (v.record) recordSize = v.bytes;
            }
        }
        std::uint64_t implied = 0;
        const Variable* last = nullptr;
        for (const Variable& v : m_variables) {
            if (v.bytes == 0 || (v.record && (streaming || m_records == 0))) continue;
            const std::uint64_t end =
                v.record ? plus(plus(v.begin, times(m_records - 1, recordSize)), v.bytes)
                         : plus(v.begin, v.bytes);
            if (end > implied) {
                implied = end;
                last = &v;
            }
        }
        if (last == nullptr || implied <= m_size) return;
        throw Error(ErrorKind::CorruptFile,
                    "'" + m_path + "' is truncated: it holds " + std::to_string(m_size) +
                        " bytes, but its header implies " + std::to_string(implied) +
                        " (the values of variable '" + last->name +
                        "' end there). Copy or download it again");
    }

    std::string m_path;
    std::ifstream m_in;
    std::uintmax_t m_size;
    bool m_cdf5 = false;
    int m_offsets = 4;
    std::uint64_t m_records = 0;
    std::vector<std::uint64_t> m_dimensions;
    std::vector<Variable> m_variables;
};

// For classic files (first bytes "CDF\1", "CDF\2", "CDF\5"); others go to nc_open unchecked.
void checkClassicHeader(const std::string& path) {
    std::array<char, 4> magic{};
    std::ifstream in(path, std::ios::binary);
    if (!in.read(magic.data(), magic.size()) || magic[0] != 'C' || magic[1] != 'D' ||
        magic[2] != 'F' || (magic[3] != 1 && magic[3] != 2 && magic[3] != 5)) {
        return;
    }
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (!error) ClassicHeader(path, size).walk();
}

// netCDF-C copies the names of a NetCDF-4 file's variables and attributes into the caller's
// NC_MAX_NAME + 1 bytes whatever their length, and HDF5 sets no limit: a plain HDF5 file with a
// 400-character dataset name overran that buffer while the reader only asked whether the file
// was NetCDF. Such names are refused here, before netCDF-C sees the file.
struct LongName {
    std::string name;
};

herr_t checkAttributeName(hid_t /*object*/, const char* name, const H5A_info_t* /*info*/,
                          void* found) {
    if (std::strlen(name) <= NC_MAX_NAME) return 0;
    static_cast<LongName*>(found)->name = name;
    return 1;  // stops the iteration
}

herr_t checkLinkName(hid_t group, const char* path, const H5L_info_t* info, void* found) {
    const char* slash = std::strrchr(path, '/');
    const char* name = slash != nullptr ? slash + 1 : path;
    if (std::strlen(name) > NC_MAX_NAME) {
        static_cast<LongName*>(found)->name = name;
        return 1;
    }
    // Soft and external links name objects elsewhere (or nowhere): only a hard link's own.
    if (info->type != H5L_TYPE_HARD) return 0;
    hsize_t at = 0;
    return H5Aiterate_by_name(group, path, H5_INDEX_NAME, H5_ITER_NATIVE, &at, checkAttributeName,
                              found, H5P_DEFAULT) > 0
               ? 1
               : 0;
}

void checkHdf5Names(const std::string& path) {
    std::array<char, 4> magic{};
    std::ifstream in(path, std::ios::binary);
    if (!in.read(magic.data(), magic.size()) || std::string(magic.data(), 4) != "\x89HDF") return;
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file < 0) return;  // nc_open says why
    LongName found;
    hsize_t at = 0;
    if (H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_NATIVE, &at, checkAttributeName, &found) <= 0) {
        H5Lvisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, checkLinkName, &found);
    }
    H5Fclose(file);
    if (!found.name.empty()) {
        throw Error(ErrorKind::UnsupportedFormat,
                    "'" + path + "' holds a name of " + std::to_string(found.name.size()) +
                        " characters ('" + found.name.substr(0, 40) +
                        "...'); NetCDF names have at most " + std::to_string(NC_MAX_NAME));
    }
}
// Attributes only netCDF-4 (or another writer of dimension scales) puts on datasets.
herr_t findNetcdfMark(hid_t group, const char* path, const H5L_info_t* info, void* found) {
    if (info->type != H5L_TYPE_HARD) return 0;
    for (const char* name :
         {"DIMENSION_LIST", "REFERENCE_LIST", "_Netcdf4Dimid", "_Netcdf4Coordinates"}) {
        if (H5Aexists_by_name(group, path, name, H5P_DEFAULT) > 0) {
            *static_cast<bool*>(found) = true;
            return 1;  // stops the visit
        }
    }
    return 0;
}
}  // namespace

bool hasNetcdf4Marks(const std::string& path) {
    quietHdf5OnThisThread();
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file < 0) return false;
    bool found = H5Aexists(file, "_NCProperties") > 0 || H5Aexists(file, "_nc3_strict") > 0;
    if (!found) H5Lvisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, findNetcdfMark, &found);
    H5Fclose(file);
    return found;
}

NetcdfFile::NetcdfFile(std::string path) : m_path(std::move(path)) {
    if (!std::filesystem::exists(m_path)) {
        throw Error(ErrorKind::FileNotFound, "no such file: '" + m_path + "'");
    }
    quietHdf5OnThisThread();
    checkClassicHeader(m_path);
    checkHdf5Names(m_path);
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
    // The destructor does not run when the constructor throws (a truncated file, a failed
    // query): without this the file stayed open, one descriptor lost on every attempt.
    struct CloseOnThrow {
        int id;
        bool armed = true;
        ~CloseOnThrow() {
            if (armed) nc_close(id);
        }
    } closeOnThrow{m_id};
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
    closeOnThrow.armed = false;
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

std::vector<std::string> NetcdfFile::readStrings(const NcVariable& var) const {
    if (var.type != NC_CHAR || var.dimIds.size() != 2) {
        throw Error(ErrorKind::InvalidArgument,
                    "'" + m_path + "': '" + var.name + "' is not a 2D character variable");
    }
    const std::size_t rows = dimension(var.dimIds[0]).size;
    const std::size_t length = dimension(var.dimIds[1]).size;
    // Validated before allocating: a header may declare sizes its file never holds.
    constexpr std::size_t kMostBytes = std::size_t{16} << 20;
    if (length != 0 && rows > kMostBytes / length) {
        throw Error(ErrorKind::InvalidArgument, "'" + m_path + "': '" + var.name + "' holds " +
                                                    std::to_string(rows) + " strings of " +
                                                    std::to_string(length) +
                                                    " characters, more than ensil reads as text");
    }
    std::vector<char> text(rows * length);
    if (!text.empty()) {
        check(nc_get_var_text(m_id, var.id, text.data()), "read variable '" + var.name + "'");
    }
    std::vector<std::string> strings;
    for (std::size_t r = 0; r < rows; ++r) {
        std::string row(text.data() + r * length, length);
        row.erase(row.find_last_not_of(std::string(" \0", 2)) + 1);
        strings.push_back(std::move(row));
    }
    return strings;
}

std::vector<double> NetcdfFile::readDoubles(const NcVariable& var,
                                            const std::vector<std::size_t>& start,
                                            const std::vector<std::size_t>& count) const {
    std::size_t n = 1;
    for (const std::size_t c : count) n *= c;
    std::vector<double> values(n);
    check(nc_get_vara_double(m_id, var.id, start.data(), count.data(), values.data()),
          "read variable '" + var.name + "'");
    return values;
}

std::optional<std::uint64_t> NetcdfFile::storedBytes(const NcVariable& var) const {
    int format = 0;
    if (nc_inq_format(m_id, &format) != NC_NOERR ||
        (format != NC_FORMAT_NETCDF4 && format != NC_FORMAT_NETCDF4_CLASSIC)) {
        return std::nullopt;
    }
    // netCDF-C has no query for this; its HDF5 file is opened a second time, read-only, which
    // HDF5 shares with netCDF's own handle.
    quietHdf5OnThisThread();
    const hid_t file = H5Fopen(m_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file < 0) return std::nullopt;
    std::optional<std::uint64_t> bytes;
    // netCDF-4 names the dataset of a variable that shares a dimension's name without being
    // its coordinate variable with this prefix.
    for (const std::string& name : {var.name, "_nc4_non_coord_" + var.name}) {
        if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0) continue;
        const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
        if (dataset < 0) continue;
        bytes = static_cast<std::uint64_t>(H5Dget_storage_size(dataset));
        H5Dclose(dataset);
        break;
    }
    H5Fclose(file);
    return bytes;
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

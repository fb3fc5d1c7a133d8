#include "data/hdf5_file.h"

#include <algorithm>
#include <string_view>
#include <utility>

#include "data/error.h"
#include "data/reader_support.h"

namespace ensil::data::hdf5 {

Handle::Handle(Handle&& other) noexcept
    : m_id(std::exchange(other.m_id, -1)), m_close(other.m_close) {}

Handle& Handle::operator=(Handle&& other) noexcept {
    if (this != &other) {
        if (m_id >= 0 && m_close) m_close(m_id);
        m_id = std::exchange(other.m_id, -1);
        m_close = other.m_close;
    }
    return *this;
}

Handle::~Handle() {
    if (m_id >= 0 && m_close) m_close(m_id);
}

QuietErrors::QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &m_function, &m_data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, m_function, m_data); }

namespace {

constexpr std::string_view kSignature{"\x89HDF\r\n\x1a\n", 8};

// The innermost entry of this thread's error stack says what actually went wrong ("truncated
// file: eof = ..."); the outer ones only repeat which API call failed.
std::string innermostError() {
    std::string message;
    H5Ewalk2(
        H5E_DEFAULT, H5E_WALK_UPWARD,
        [](unsigned n, const H5E_error2_t* err, void* data) -> herr_t {
            if (n == 0 && err->desc) *static_cast<std::string*>(data) = err->desc;
            return 0;
        },
        &message);
    return message;
}

std::string typeProblem(hid_t type) {
    switch (H5Tget_class(type)) {
        case H5T_INTEGER:
        case H5T_FLOAT:
            return {};
        case H5T_STRING:
            return "strings";
        case H5T_COMPOUND:
            return "compound records";
        case H5T_ENUM:
            return "enumeration values";
        case H5T_ARRAY:
            return "fixed-size arrays";
        case H5T_VLEN:
            return "variable-length sequences";
        case H5T_OPAQUE:
            return "opaque bytes";
        case H5T_BITFIELD:
            return "bit fields";
        case H5T_REFERENCE:
            return "object references";
        default:
            return "values of an unknown type";
    }
}

struct Listing {
    std::vector<std::string> datasets;
    std::vector<std::string> groups{"/"};
};

herr_t visitLink(hid_t group, const char* name, const H5L_info_t* info, void* data) {
    if (info->type != H5L_TYPE_HARD) return 0;  // soft and external links point elsewhere
    const Handle object(H5Oopen(group, name, H5P_DEFAULT), H5Oclose);
    if (!object.valid()) return 0;
    auto* listing = static_cast<Listing*>(data);
    const H5I_type_t type = H5Iget_type(object.get());
    if (type == H5I_DATASET) listing->datasets.push_back("/" + std::string(name));
    if (type == H5I_GROUP) listing->groups.push_back("/" + std::string(name));
    return 0;
}

// HDF5 refuses to convert between character sets, so the memory type copies the file's.
std::optional<std::string> textAttribute(hid_t object, const char* name) {
    if (H5Aexists(object, name) <= 0) return std::nullopt;
    const Handle attr(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
    const Handle type(H5Aget_type(attr.get()), H5Tclose);
    if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING) return std::nullopt;
    const Handle space(H5Aget_space(attr.get()), H5Sclose);
    const auto count = H5Sget_simple_extent_npoints(space.get());
    if (count < 1) return std::nullopt;
    const Handle memType(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_cset(memType.get(), H5Tget_cset(type.get()));
    std::string text;
    if (H5Tis_variable_str(type.get()) > 0) {
        H5Tset_size(memType.get(), H5T_VARIABLE);
        std::vector<char*> strings(static_cast<std::size_t>(count), nullptr);
        if (H5Aread(attr.get(), memType.get(), strings.data()) < 0) return std::nullopt;
        if (strings.front()) text = strings.front();
        for (char* s : strings) H5free_memory(s);
    } else {
        const std::size_t size = H5Tget_size(type.get());
        H5Tset_size(memType.get(), size);
        std::string buffer(size * static_cast<std::size_t>(count), '\0');
        if (H5Aread(attr.get(), memType.get(), buffer.data()) < 0) return std::nullopt;
        text = buffer.substr(0, size);
        text = text.substr(0, text.find('\0'));
        text.erase(text.find_last_not_of(' ') + 1);
    }
    return text;
}

// Present but not numeric yields an empty vector, so callers can say so.
std::optional<std::vector<double>> numberAttribute(hid_t object, const char* name) {
    if (H5Aexists(object, name) <= 0) return std::nullopt;
    const Handle attr(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
    const Handle type(H5Aget_type(attr.get()), H5Tclose);
    if (!type.valid() || !typeProblem(type.get()).empty()) return std::vector<double>{};
    const Handle space(H5Aget_space(attr.get()), H5Sclose);
    const auto count = H5Sget_simple_extent_npoints(space.get());
    std::vector<double> values(static_cast<std::size_t>(std::max<hssize_t>(count, 0)));
    if (values.empty() || H5Aread(attr.get(), H5T_NATIVE_DOUBLE, values.data()) < 0) return {};
    return values;
}

}  // namespace

std::string normalizePath(const std::string& path) {
    std::string result = path.empty() || path.front() != '/' ? "/" + path : path;
    while (result.size() > 1 && result.back() == '/') result.pop_back();
    return result;
}

std::string baseName(const std::string& path) { return path.substr(path.rfind('/') + 1); }

File::File(std::string path) : m_path(std::move(path)) {
    if (readFileStart(m_path, kSignature.size()) != kSignature) {
        throw Error(ErrorKind::UnsupportedFormat,
                    "'" + m_path +
                        "' is not an HDF5 file: it does not start with the HDF5 "
                        "signature");
    }
    m_file = Handle(H5Fopen(m_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!m_file.valid()) fail("open it; it may be truncated or damaged");
}

void File::fail(const std::string& what) const {
    const std::string reason = innermostError();
    throw Error(ErrorKind::CorruptFile, "HDF5 file '" + m_path + "': cannot " + what +
                                            (reason.empty() ? "" : " (HDF5: " + reason + ")"));
}

File::Contents File::contents() const {
    Listing listing;
    if (H5Lvisit(id(), H5_INDEX_NAME, H5_ITER_INC, visitLink, &listing) < 0) {
        fail("list the contents");
    }
    Contents result;
    for (const std::string& path : listing.datasets) result.datasets.push_back(inspect(path));
    result.groups = std::move(listing.groups);
    return result;
}

namespace {
H5I_type_t objectType(hid_t file, const std::string& path) {
    if (path == "/") return H5I_GROUP;
    // H5Oopen fails (quietly) when a link on the way is missing, so no H5Lexists walk is needed.
    const Handle object(H5Oopen(file, path.c_str(), H5P_DEFAULT), H5Oclose);
    return object.valid() ? H5Iget_type(object.get()) : H5I_BADID;
}
}  // namespace

bool File::isDataset(const std::string& path) const {
    return objectType(id(), path) == H5I_DATASET;
}

bool File::isGroup(const std::string& path) const { return objectType(id(), path) == H5I_GROUP; }

Handle File::open(const std::string& path) const {
    Handle object(H5Oopen(id(), path.c_str(), H5P_DEFAULT), H5Oclose);
    if (!object.valid()) fail("open '" + path + "'");
    return object;
}

DatasetInfo File::inspect(const std::string& datasetPath) const {
    const Handle dataset = open(datasetPath);
    const Handle space(H5Dget_space(dataset.get()), H5Sclose);
    const Handle type(H5Dget_type(dataset.get()), H5Tclose);
    const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
    if (rank < 0 || !type.valid()) fail("read the shape of dataset '" + datasetPath + "'");
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    DatasetInfo info;
    info.path = datasetPath;
    info.shape.assign(dims.begin(), dims.end());
    info.typeProblem = typeProblem(type.get());
    return info;
}

Attributes File::attributes(const std::string& objectPath) const {
    const Handle object = open(objectPath);
    Attributes result;
    result.units = textAttribute(object.get(), "units").value_or("");
    result.longName = textAttribute(object.get(), "long_name").value_or("");
    const auto triple = [&](const char* name) -> std::optional<std::array<double, 3>> {
        const auto values = numberAttribute(object.get(), name);
        if (!values) return std::nullopt;
        if (values->size() != 3) {
            throw Error(ErrorKind::InvalidArgument,
                        "attribute '" + std::string(name) + "' of '" + objectPath + "' in '" +
                            m_path + "' must hold 3 numbers (x, y, z), it holds " +
                            (values->empty() ? "no numbers" : std::to_string(values->size())));
        }
        return std::array<double, 3>{(*values)[0], (*values)[1], (*values)[2]};
    };
    result.origin = triple("origin");
    result.spacing = triple("spacing");
    for (const char* name : {"_FillValue", "missing_value"}) {
        const auto values = numberAttribute(object.get(), name);
        if (values)
            result.missingValues.insert(result.missingValues.end(), values->begin(), values->end());
    }
    return result;
}

void File::read(const std::string& datasetPath, const std::vector<std::size_t>& start,
                const std::vector<std::size_t>& count, float* out) const {
    const Handle dataset = open(datasetPath);
    const Handle fileSpace(H5Dget_space(dataset.get()), H5Sclose);
    const std::vector<hsize_t> offset(start.begin(), start.end());
    const std::vector<hsize_t> block(count.begin(), count.end());
    hsize_t total = 1;
    for (const hsize_t n : block) total *= n;
    const Handle memSpace(H5Screate_simple(1, &total, nullptr), H5Sclose);
    if (!fileSpace.valid() || !memSpace.valid() ||
        H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, offset.data(), nullptr, block.data(),
                            nullptr) < 0 ||
        H5Dread(dataset.get(), H5T_NATIVE_FLOAT, memSpace.get(), fileSpace.get(), H5P_DEFAULT,
                out) < 0) {
        fail("read dataset '" + datasetPath + "'");
    }
}

}  // namespace ensil::data::hdf5

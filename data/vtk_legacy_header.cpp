#include "data/vtk_legacy_header.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "data/ascii_case.h"
#include "data/error.h"

namespace ensil::data::vtk {
namespace {

// Legacy files write spaces and other special characters in names as %XX.
std::string decodeName(const std::string& text) {
    std::string name;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '%' && i + 2 < text.size() && std::isxdigit(text[i + 1]) &&
            std::isxdigit(text[i + 2])) {
            name += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            name += text[i];
        }
    }
    return name;
}

// Bytes per value in a binary file, in the order vtkDataReader matches type names (by prefix);
// 0 for bit arrays (packed 8 to a byte) and for types that cannot be skipped by size.
std::size_t binarySize(const std::string& type) {
    if (type.starts_with("bit")) return 0;
    if (type == "char" || type == "signed_char" || type.starts_with("unsigned_char")) return 1;
    if (type.starts_with("short") || type.starts_with("unsigned_short")) return 2;
    if (type.starts_with("vtkidtype")) return 4;  // vtkDataWriter writes ids as int
    if (type.starts_with("int") || type.starts_with("unsigned_int")) return 4;
    if (type.starts_with("long") || type.starts_with("unsigned_long")) return sizeof(long);
    if (type.starts_with("vtktypeint64") || type.starts_with("vtktypeuint64")) return 8;
    if (type.starts_with("float")) return 4;
    if (type.starts_with("double")) return 8;
    return std::numeric_limits<std::size_t>::max();
}

// Binary legacy files are big-endian.
template <typename T>
double bigEndian(const char* bytes) {
    std::array<char, sizeof(T)> copy{};
    std::memcpy(copy.data(), bytes, sizeof(T));
    if constexpr (std::endian::native == std::endian::little) std::ranges::reverse(copy);
    T value{};
    std::memcpy(&value, copy.data(), sizeof(T));
    return static_cast<double>(value);
}

double decodeBinary(const std::string& type, const char* bytes) {
    if (type.starts_with("float")) return bigEndian<float>(bytes);
    if (type.starts_with("double")) return bigEndian<double>(bytes);
    if (type.starts_with("unsigned_char")) return bigEndian<std::uint8_t>(bytes);
    if (type == "char" || type == "signed_char") return bigEndian<std::int8_t>(bytes);
    if (type.starts_with("short")) return bigEndian<std::int16_t>(bytes);
    if (type.starts_with("unsigned_short")) return bigEndian<std::uint16_t>(bytes);
    if (type.starts_with("int") || type.starts_with("vtkidtype")) {
        return bigEndian<std::int32_t>(bytes);
    }
    if (type.starts_with("unsigned_int")) return bigEndian<std::uint32_t>(bytes);
    if (type.starts_with("unsigned") || type.starts_with("vtktypeuint64")) {
        return bigEndian<std::uint64_t>(bytes);
    }
    return bigEndian<std::int64_t>(bytes);
}

class Scanner {
public:
    explicit Scanner(const std::string& path) : m_path(path), m_in(path, std::ios::binary) {
        std::error_code ec;
        m_size = std::filesystem::file_size(path, ec);
        if (!m_in || ec) throw Error(ErrorKind::FileNotFound, "cannot open '" + path + "'");
    }

    LegacyStructure scan();

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(ErrorKind::CorruptFile, "legacy VTK file '" + m_path + "' " + what);
    }
    std::string line() {
        std::string text;
        if (!std::getline(m_in, text)) fail("ends inside its header");
        if (!text.empty() && text.back() == '\r') text.pop_back();
        return text;
    }
    bool token(std::string& text) { return static_cast<bool>(m_in >> text); }
    std::string need(const std::string& what) {
        std::string text;
        if (!token(text)) fail("ends where " + what + " should be");
        return text;
    }
    template <typename T>
    T number(const std::string& what) {
        T value{};
        if (!(m_in >> value)) fail("has no valid " + what);
        return value;
    }
    // A count of values the file must hold: digits only (a sign is refused, where a plain read
    // into an unsigned number would wrap -5 around to 2^64 - 5), and no more values than the
    // file has bytes, so nothing is allocated for values that cannot be there.
    std::size_t count(const std::string& what) {
        std::string text;
        if (!token(text)) fail("ends where " + what + " should be");
        std::size_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (text.empty() || error != std::errc{} || end != text.data() + text.size()) {
            fail("gives '" + text + "' as " + what +
                 ", which must be a whole number without a sign");
        }
        if (value > m_size) {
            fail("gives " + what + " " + text + ", more values than its " + std::to_string(m_size) +
                 " bytes can hold");
        }
        return value;
    }
    std::array<double, 3> triple(const std::string& what) {
        return {number<double>(what), number<double>(what), number<double>(what)};
    }

    void skipValues(const std::string& type, std::size_t count, const std::string& what);
    std::vector<double> readValues(const std::string& type, std::size_t count,
                                   const std::string& what);
    void skipMetadata();
    bool metadataFollows();
    void geometry(LegacyStructure& s, const std::string& keyword);
    void attribute(LegacyStructure& s, const std::string& keyword);
    void fieldArrays(LegacyStructure* s, std::size_t arrays);
    void recordAndSkip(LegacyStructure* s, const std::string& name, const std::string& type,
                       std::size_t components, std::size_t tuples);

    std::string m_path;
    std::ifstream m_in;
    std::uintmax_t m_size = 0;
    bool m_binary = false;
    bool m_pointSection = false;
    std::size_t m_tuples = 0;
    std::size_t m_components = 1;  // of the array read last, for its COMPONENT_NAMES
};

void Scanner::skipValues(const std::string& type, std::size_t count, const std::string& what) {
    const std::size_t size = binarySize(type);
    if (size == std::numeric_limits<std::size_t>::max()) {
        throw Error(ErrorKind::UnsupportedFormat, "legacy VTK file '" + m_path + "': " + what +
                                                      " holds " + type +
                                                      " values; ensil reads numeric arrays only");
    }
    if (count == 0) return;
    if (!m_binary) {
        std::string value;
        for (std::size_t i = 0; i < count; ++i) {
            if (!token(value)) {
                fail("ends inside " + what + " (after " + std::to_string(i) + " of " +
                     std::to_string(count) + " values): it is truncated");
            }
        }
        return;
    }
    std::string rest;
    std::getline(m_in, rest);  // the end of the header line; the values start after it
    const std::uintmax_t bytes = size == 0 ? (count + 7) / 8 : count * size;
    const auto at = static_cast<std::uintmax_t>(m_in.tellg());
    if (!m_in || at + bytes > m_size) {
        fail("ends inside " + what + ": it needs " + std::to_string(bytes) + " bytes, " +
             std::to_string(m_size - std::min(m_size, at)) + " are left (truncated file)");
    }
    m_in.seekg(static_cast<std::streamoff>(bytes), std::ios::cur);
}

std::vector<double> Scanner::readValues(const std::string& type, std::size_t count,
                                        const std::string& what) {
    std::vector<double> values(count);
    if (!m_binary) {
        for (double& v : values) v = number<double>(what);
        return values;
    }
    const std::size_t size = binarySize(type);
    if (size == 0 || size > 8) fail("stores " + what + " as " + type);
    std::string rest;
    std::getline(m_in, rest);
    std::vector<char> bytes(count * size);
    if (!m_in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()))) {
        fail("ends inside " + what + " (truncated file)");
    }
    for (std::size_t i = 0; i < count; ++i) values[i] = decodeBinary(type, &bytes[i * size]);
    return values;
}

// The METADATA block VTK 5.1+ writers may put after any array (the METADATA keyword has just
// been read): lines up to the first empty one, as vtkDataReader reads it, except that the
// COMPONENT_NAMES line is followed by one line per component of the array before it, empty
// for a component without a name. INFORMATION keys (NAME ... LOCATION ... and DATA lines)
// are skipped with the rest.
void Scanner::skipMetadata() {
    std::string text;
    std::getline(m_in, text);  // the end of the METADATA line
    while (std::getline(m_in, text)) {
        if (!text.empty() && text.back() == '\r') text.pop_back();
        if (text.empty()) return;
        if (asciiLower(text).starts_with("component_names")) {
            for (std::size_t c = 0; c < m_components; ++c) {
                if (!std::getline(m_in, text)) return;
            }
        }
    }
}

// Whether the next word is METADATA; if so, skips its block. Otherwise the stream is left as
// it was.
bool Scanner::metadataFollows() {
    const std::streampos at = m_in.tellg();
    std::string word;
    if (token(word) && asciiLower(word) == "metadata") {
        skipMetadata();
        return true;
    }
    m_in.clear();
    m_in.seekg(at);
    return false;
}

void Scanner::recordAndSkip(LegacyStructure* s, const std::string& name, const std::string& type,
                            std::size_t components, std::size_t tuples) {
    if (s) s->pointArrays.push_back({name, type, components});
    m_components = components;
    if (tuples > 0 && components > m_size / tuples) {
        fail("declares " + std::to_string(components) + " x " + std::to_string(tuples) +
             " values in array '" + name + "', more than its " + std::to_string(m_size) +
             " bytes can hold");
    }
    skipValues(type, components * tuples, "array '" + name + "'");
}

// `s` is null for field data that belongs to the dataset rather than to its points.
void Scanner::fieldArrays(LegacyStructure* s, std::size_t arrays) {
    for (std::size_t i = 0; i < arrays; ++i) {
        const std::string name = decodeName(need("a field array name"));
        if (name == "NULL_ARRAY") continue;
        const auto components = count("the component count of '" + name + "'");
        const auto tuples = count("the tuple count of '" + name + "'");
        const std::string type = asciiLower(need("the type of '" + name + "'"));
        recordAndSkip(s, name, type, components, tuples);
        metadataFollows();  // as vtkDataReader looks for it: after every array
    }
}

void Scanner::geometry(LegacyStructure& s, const std::string& keyword) {
    if (keyword == "dimensions") {
        std::size_t points = 1;
        for (std::size_t& n : s.dimensions) {
            n = count("a DIMENSIONS size");
            if (n == 0) fail("gives 0 in its DIMENSIONS: every axis needs at least one point");
            points = n > m_size * 8 / points ? m_size * 8 + 1 : points * n;
        }
        // Every point needs at least one bit of data in the file.
        if (points > m_size * 8) {
            fail("declares DIMENSIONS of " + std::to_string(s.dimensions[0]) + " x " +
                 std::to_string(s.dimensions[1]) + " x " + std::to_string(s.dimensions[2]) +
                 " points, more than its " + std::to_string(m_size) + " bytes can hold");
        }
    } else if (keyword == "origin") {
        s.origin = triple("ORIGIN");
    } else if (keyword == "spacing" || keyword == "aspect_ratio") {
        s.spacing = triple("SPACING");
    } else if (keyword.size() == 13 && keyword.ends_with("_coordinates")) {
        const auto axis = static_cast<std::size_t>(keyword[0] - 'x');
        if (axis > 2) fail("has an unknown keyword '" + keyword + "'");
        const auto values = count(keyword + " count");
        const std::string type = asciiLower(need(keyword + " type"));
        s.coordinates[axis] = readValues(type, values, keyword);
        m_components = 1;
    } else if (keyword == "field") {
        need("a field name");
        fieldArrays(nullptr, count("field array count"));
    } else {
        fail("has an unknown keyword '" + keyword + "' in its " + s.dataset + " geometry");
    }
}

// Components of the attribute kinds whose header is just "KIND name type"; 0 for other kinds.
std::size_t fixedComponents(const std::string& keyword) {
    if (keyword == "vectors" || keyword == "normals") return 3;
    if (keyword == "tensors") return 9;
    if (keyword == "tensors6") return 6;
    if (keyword == "global_ids" || keyword == "pedigree_ids") return 1;
    return 0;
}

void Scanner::attribute(LegacyStructure& s, const std::string& keyword) {
    LegacyStructure* record = m_pointSection ? &s : nullptr;
    if (keyword == "field") {
        need("a field name");
        fieldArrays(record, count("field array count"));
    } else if (keyword == "scalars") {
        const std::string name = decodeName(need("a scalar array name"));
        const std::string type = asciiLower(need("the type of '" + name + "'"));
        std::string next = asciiLower(need("LOOKUP_TABLE"));
        std::size_t count = 1;
        if (next != "lookup_table") {
            count = static_cast<std::size_t>(std::max(1, std::atoi(next.c_str())));
            next = asciiLower(need("LOOKUP_TABLE"));
        }
        if (next != "lookup_table") fail("has no LOOKUP_TABLE after scalars '" + name + "'");
        need("a lookup table name");
        recordAndSkip(record, name, type, count, m_tuples);
    } else if (keyword == "color_scalars") {
        const std::string name = decodeName(need("a color scalar name"));
        const auto components = count("the color component count");
        recordAndSkip(record, name, m_binary ? "unsigned_char" : "float", components, m_tuples);
    } else if (keyword == "lookup_table") {
        const std::string name = need("a lookup table name");
        const auto size = count("the lookup table size");
        skipValues(m_binary ? "unsigned_char" : "float", 4 * size, "lookup table '" + name + "'");
    } else if (keyword == "texture_coordinates") {
        const std::string name = decodeName(need("a texture coordinate name"));
        const auto dim = count("the texture coordinate dimension");
        recordAndSkip(record, name, asciiLower(need("the type of '" + name + "'")), dim, m_tuples);
    } else if (const std::size_t components = fixedComponents(keyword); components > 0) {
        const std::string name = decodeName(need("an array name"));
        recordAndSkip(record, name, asciiLower(need("the type of '" + name + "'")), components,
                      m_tuples);
    } else {
        fail("has an unknown keyword '" + keyword + "' among its point and cell data");
    }
}

LegacyStructure Scanner::scan() {
    LegacyStructure s;
    if (!line().starts_with("# vtk DataFile")) fail("does not start with '# vtk DataFile'");
    line();                                                          // the title
    const std::string format = asciiLower(need("ASCII or BINARY"));  // blank lines may come first
    if (!format.starts_with("ascii") && !format.starts_with("binary")) {
        fail("says '" + format + "' where ASCII or BINARY should be");
    }
    s.binary = format.starts_with("binary");
    m_binary = s.binary;
    if (asciiLower(need("DATASET")) != "dataset") fail("has no DATASET line");
    std::string keyword = need("the dataset type");
    std::ranges::transform(keyword, keyword.begin(),
                           [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    s.dataset = keyword;
    if (s.dataset != "STRUCTURED_POINTS" && s.dataset != "RECTILINEAR_GRID") return s;
    bool attributes = false;
    while (token(keyword)) {
        keyword = asciiLower(keyword);
        if (keyword == "point_data" || keyword == "cell_data") {
            attributes = true;
            m_pointSection = keyword == "point_data";
            m_tuples =
                count(keyword == "point_data" ? "the POINT_DATA count" : "the CELL_DATA count");
        } else if (keyword == "metadata") {
            skipMetadata();
        } else if (attributes) {
            attribute(s, keyword);
        } else {
            geometry(s, keyword);
        }
    }
    return s;
}

}  // namespace

LegacyStructure scanLegacyFile(const std::string& path) { return Scanner(path).scan(); }

}  // namespace ensil::data::vtk

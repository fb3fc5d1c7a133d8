#include "preprocessing/mesh_cache.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include "data/error.h"

namespace ensil::prep {
namespace {

constexpr std::array<char, 8> kMagic{'E', 'N', 'S', 'I', 'L', 'M', 'C', '1'};

class Writer {
public:
    template <typename T>
    void put(const T& value) {
        const auto* p = reinterpret_cast<const char*>(&value);
        m_bytes.insert(m_bytes.end(), p, p + sizeof(T));
    }
    void putBytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const char*>(data);
        m_bytes.insert(m_bytes.end(), p, p + size);
    }
    [[nodiscard]] const std::vector<char>& bytes() const { return m_bytes; }

private:
    std::vector<char> m_bytes;
};

class Reader {
public:
    explicit Reader(const std::vector<char>& bytes) : m_bytes(bytes) {}
    template <typename T>
    T get() {
        T value{};
        getBytes(&value, sizeof(T));
        return value;
    }
    void getBytes(void* out, std::size_t size) {
        // An empty mesh (a member without a surface at the isovalue) reads 0 bytes into an
        // empty vector, whose data() may be null: memcpy from or to null is undefined even then.
        if (size == 0) return;
        if (size > m_bytes.size() - m_offset) throw std::runtime_error("truncated entry");
        std::memcpy(out, m_bytes.data() + m_offset, size);
        m_offset += size;
    }
    [[nodiscard]] bool atEnd() const { return m_offset == m_bytes.size(); }
    [[nodiscard]] std::size_t left() const { return m_bytes.size() - m_offset; }

private:
    const std::vector<char>& m_bytes;
    std::size_t m_offset = 0;
};

void putMesh(Writer& w, const data::PackedMesh& m) {
    w.put(m.boundsMin);
    w.put(m.boundsMax);
    w.put(m.outlyingnessScale);
    w.put(static_cast<std::uint64_t>(m.vertices.size()));
    w.put(static_cast<std::uint64_t>(m.indices.size()));
    w.putBytes(m.vertices.data(), m.vertices.size() * sizeof(data::PackedVertex));
    w.putBytes(m.indices.data(), m.indices.size() * sizeof(std::uint32_t));
}

data::PackedMesh getMesh(Reader& r) {
    data::PackedMesh m;
    m.boundsMin = r.get<glm::vec3>();
    m.boundsMax = r.get<glm::vec3>();
    m.outlyingnessScale = r.get<float>();
    const auto vertices = r.get<std::uint64_t>();
    const auto indices = r.get<std::uint64_t>();
    // Counts are checked against the bytes the entry holds before anything is allocated.
    if (vertices > r.left() / sizeof(data::PackedVertex) ||
        indices > (r.left() - vertices * sizeof(data::PackedVertex)) / sizeof(std::uint32_t)) {
        throw std::runtime_error("sizes beyond the entry");
    }
    m.vertices.resize(vertices);
    m.indices.resize(indices);
    r.getBytes(m.vertices.data(), vertices * sizeof(data::PackedVertex));
    r.getBytes(m.indices.data(), indices * sizeof(std::uint32_t));
    for (std::uint32_t i : m.indices) {
        if (i >= vertices) throw std::runtime_error("index out of range");
    }
    return m;
}

std::vector<char> serialise(const IsovalueMeshes& s) {
    Writer w;
    w.put(s.isovalue);
    w.put(static_cast<std::uint32_t>(s.members.size()));
    w.put(s.seconds);
    w.put(static_cast<std::uint64_t>(s.trianglesExtracted));
    w.put(static_cast<std::uint64_t>(s.triangles));
    w.put(static_cast<std::uint64_t>(s.vertices));
    w.put(s.worstErrorCells);
    putMesh(w, s.mean);
    for (const data::PackedMesh& m : s.members) putMesh(w, m);
    return w.bytes();
}

IsovalueMeshes deserialise(const std::vector<char>& payload) {
    Reader r(payload);
    IsovalueMeshes s;
    s.isovalue = r.get<float>();
    const auto members = r.get<std::uint32_t>();
    s.seconds = r.get<StageSeconds>();
    s.trianglesExtracted = r.get<std::uint64_t>();
    s.triangles = r.get<std::uint64_t>();
    s.vertices = r.get<std::uint64_t>();
    s.worstErrorCells = r.get<float>();
    s.mean = getMesh(r);
    // Every mesh takes at least its bounds, scale and two counts: a member count beyond what
    // the entry can hold is not believed (nor reserved for).
    constexpr std::size_t kMeshHeadBytes = 7 * sizeof(float) + 2 * sizeof(std::uint64_t);
    if (members > r.left() / kMeshHeadBytes) throw std::runtime_error("members beyond the entry");
    s.members.reserve(members);
    for (std::uint32_t m = 0; m < members; ++m) s.members.push_back(getMesh(r));
    if (!r.atEnd()) throw std::runtime_error("trailing bytes");
    return s;
}

}  // namespace

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t seed) {
    std::uint64_t h = seed;
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 0x100000001b3ULL;
    return h;
}

std::string pipelineKey(const PipelineOptions& options, float verticalExaggeration) {
    std::ostringstream key;
    key.precision(9);  // round-trips a float exactly
    key << "isovalue=" << options.isovalue << " decimate=" << options.decimate
        << " error=" << options.maxErrorCells << " exaggeration=" << verticalExaggeration
        << " format=" << kCacheFormatVersion << " meshes=" << kMeshMakingVersion;
    return key.str();
}

MeshCache::MeshCache(std::filesystem::path directory, std::uintmax_t maxBytes)
    : m_directory(std::move(directory)), m_maxBytes(maxBytes) {}

std::filesystem::path MeshCache::pathFor(const std::string& key) const {
    std::array<char, 17> hex{};
    std::snprintf(hex.data(), hex.size(), "%016llx",
                  static_cast<unsigned long long>(fnv1a(key.data(), key.size())));
    return m_directory / (std::string(hex.data()) + ".ensilmesh");
}

std::optional<IsovalueMeshes> MeshCache::load(const std::string& key) const {
    const std::filesystem::path path = pathFor(key);
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    try {
        std::array<char, 8> magic{};
        std::uint32_t version = 0, keyLength = 0;
        in.read(magic.data(), magic.size());
        in.read(reinterpret_cast<char*>(&version), sizeof version);
        in.read(reinterpret_cast<char*>(&keyLength), sizeof keyLength);
        if (!in || magic != kMagic || version != kCacheFormatVersion || keyLength > (1U << 20)) {
            throw std::runtime_error("bad header");
        }
        std::string storedKey(keyLength, '\0');
        in.read(storedKey.data(), keyLength);
        if (storedKey != key) return std::nullopt;  // another key with the same hash: a miss
        std::uint64_t size = 0, checksum = 0;
        in.read(reinterpret_cast<char*>(&size), sizeof size);
        in.read(reinterpret_cast<char*>(&checksum), sizeof checksum);
        // The payload is the rest of the file: a length field that says more is not believed
        // (nor allocated for).
        std::error_code sizeError;
        const std::uintmax_t fileSize = std::filesystem::file_size(path, sizeError);
        const auto at = static_cast<std::uintmax_t>(in.tellg());
        if (!in || sizeError || at > fileSize || size != fileSize - at) {
            throw std::runtime_error("bad header");
        }
        std::vector<char> payload(size);
        in.read(payload.data(), static_cast<std::streamsize>(size));
        if (!in || fnv1a(payload.data(), payload.size()) != checksum) {
            throw std::runtime_error("checksum");
        }
        IsovalueMeshes meshes = deserialise(payload);
        std::error_code ignored;
        std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(),
                                         ignored);
        return meshes;
    } catch (const std::exception&) {
        // Never trust a damaged entry: remove it so it is rebuilt.
        in.close();
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
        return std::nullopt;
    }
}

void MeshCache::store(const std::string& key, const IsovalueMeshes& meshes) const {
    std::error_code error;
    std::filesystem::create_directories(m_directory, error);
    const std::filesystem::path path = pathFor(key);
    std::random_device device;
    const std::filesystem::path temporary = path.string() + ".tmp" + std::to_string(device());
    const std::vector<char> payload = serialise(meshes);
    const std::uint64_t size = payload.size(), checksum = fnv1a(payload.data(), payload.size());
    const auto keyLength = static_cast<std::uint32_t>(key.size());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(kMagic.data(), kMagic.size());
        out.write(reinterpret_cast<const char*>(&kCacheFormatVersion), sizeof kCacheFormatVersion);
        out.write(reinterpret_cast<const char*>(&keyLength), sizeof keyLength);
        out.write(key.data(), static_cast<std::streamsize>(key.size()));
        out.write(reinterpret_cast<const char*>(&size), sizeof size);
        out.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
        out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
        out.flush();
        if (!out) {
            out.close();
            std::filesystem::remove(temporary, error);
            throw data::Error(data::ErrorKind::WriteFailed,
                              "cannot write the preprocessing cache in '" + m_directory.string() +
                                  "' (is the disk full or the folder read-only?)");
        }
    }
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        throw data::Error(data::ErrorKind::WriteFailed,
                          "cannot write the preprocessing cache entry '" + path.string() + "'");
    }
    trim();
}

void MeshCache::trim() const {
    std::vector<std::pair<std::filesystem::file_time_type, std::filesystem::path>> entries;
    std::uintmax_t total = 0;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(m_directory, error)) {
        if (entry.path().extension() != ".ensilmesh") continue;
        total += entry.file_size(error);
        entries.emplace_back(entry.last_write_time(error), entry.path());
    }
    std::sort(entries.begin(), entries.end());  // oldest first
    for (const auto& [time, path] : entries) {
        if (total <= m_maxBytes) break;
        total -= std::filesystem::file_size(path, error);
        std::filesystem::remove(path, error);
    }
}

}  // namespace ensil::prep

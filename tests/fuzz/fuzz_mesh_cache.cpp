// Fuzzes the mesh cache reader (preprocessing/mesh_cache.h, MeshCache::load). Cache entries
// live on disk between runs, so a damaged, truncated or foreign file in the cache folder must
// come back as a miss, never as a crash or an allocation its size cannot justify. The first
// byte picks what the rest is: even, the whole entry file as stored (the header checks: magic,
// version, key length, payload length against the file's size); odd, the payload alone, which
// the target wraps in a valid header with the right key and FNV-1a checksum, so the mesh
// counts, bounds and indices behind the checksum are reached too (a 64-bit checksum is a wall
// that random mutation does not get through).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "preprocessing/mesh_cache.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

constexpr const char* kKey = "fuzz";

// A private cache folder for this process, removed at exit.
struct CacheFolder {
    CacheFolder() {
        std::string pattern = ensil::fuzz::temporaryFolder() + "/ensil-fuzz-cache-XXXXXX";
        if (mkdtemp(pattern.data()) == nullptr) ensil::fuzz::unexpected("mkdtemp failed");
        path = pattern;
    }
    ~CacheFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
    std::filesystem::path path;
};

template <typename T>
void append(std::string& bytes, const T& value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// The header MeshCache::store writes (mesh_cache.h) in front of `payload`.
std::string wrapped(const std::uint8_t* payload, std::size_t size) {
    std::string bytes = "ENSILMC1";
    append(bytes, ensil::prep::kCacheFormatVersion);
    append(bytes, static_cast<std::uint32_t>(std::strlen(kKey)));
    bytes += kKey;
    append(bytes, static_cast<std::uint64_t>(size));
    append(bytes, ensil::prep::fnv1a(payload, size));
    bytes.append(reinterpret_cast<const char*>(payload), size);
    return bytes;
}

}  // namespace

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const CacheFolder folder;
    static const ensil::prep::MeshCache cache(folder.path);
    if (size == 0) return 0;
    const std::string entry = (data[0] & 1) != 0
                                  ? wrapped(data + 1, size - 1)
                                  : std::string(reinterpret_cast<const char*>(data + 1), size - 1);
    {
        std::ofstream out(cache.pathFor(kKey), std::ios::binary | std::ios::trunc);
        out.write(entry.data(), static_cast<std::streamsize>(entry.size()));
        if (!out) ensil::fuzz::unexpected("cannot write the cache entry");
    }
    try {
        const auto meshes = cache.load(kKey);
        ensil::fuzz::note(meshes ? "a hit" : "a miss");
        if (meshes) {
            // A hit promises indices within each mesh's vertices (the renderer trusts them).
            const auto checkIndices = [](const ensil::data::PackedMesh& mesh) {
                for (const std::uint32_t i : mesh.indices) {
                    if (i >= mesh.vertices.size()) ensil::fuzz::unexpected("index out of range");
                }
            };
            checkIndices(meshes->mean);
            for (const auto& mesh : meshes->members) checkIndices(mesh);
        }
    } catch (const std::exception& e) {
        ensil::fuzz::unexpected(e);  // load() reports every failure as a miss
    }
    return 0;
}

// A disk cache of preprocessed isovalues, so reopening an ensemble at a known isovalue is
// instant. One file per entry, named by a hash of its key; the key (input files with their
// sizes and modification times, variable, member dimension, time index, isovalue, decimation,
// vertical exaggeration, format and mesh-making versions) is stored inside and compared on load, so
// a hash collision or a changed input is never trusted.
//
// File format (little-endian, as written by the machine that reads it; the cache is local):
//   8 bytes  magic "ENSILMC1"
//   u32      format version (kCacheFormatVersion)
//   u32      key length K, then K bytes of key text
//   u64      payload length P
//   u64      FNV-1a 64 checksum of the payload
//   P bytes  payload: isovalue f32, member count u32, stage seconds 3 x f64, counts, worst
//            error f32, then the mean and every member mesh: bounds 6 x f32, outlyingness
//            scale f32, vertex count u64, index count u64, 20-byte vertices, u32 indices.
// Entries are written to a temporary file and renamed into place, so a crash or a cancel never
// leaves half an entry. A file that fails any check is deleted and reported as a miss.
// Thread-safe for distinct keys; callers serialise stores of the same key.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "preprocessing/isosurface_pipeline.h"

namespace ensil::prep {

inline constexpr std::uint32_t kCacheFormatVersion = 1;
// How the meshes are made (marching cubes, decimation): part of the key, so that entries made
// by an earlier way are not shown as this one's. 2: ensil's own simplification.
inline constexpr std::uint32_t kMeshMakingVersion = 2;

class MeshCache {
public:
    // maxBytes: the cache trims its oldest entries beyond this size after each store.
    explicit MeshCache(std::filesystem::path directory,
                       std::uintmax_t maxBytes = std::uintmax_t{2} << 30);

    [[nodiscard]] std::optional<IsovalueMeshes> load(const std::string& key) const;
    // Throws data::Error(WriteFailed) when the folder is not writable or the disk is full.
    void store(const std::string& key, const IsovalueMeshes& meshes) const;
    [[nodiscard]] std::filesystem::path pathFor(const std::string& key) const;
    [[nodiscard]] const std::filesystem::path& directory() const { return m_directory; }

private:
    void trim() const;

    std::filesystem::path m_directory;
    std::uintmax_t m_maxBytes;
};

// The part of a cache key that says which isovalue and how it was processed.
std::string pipelineKey(const PipelineOptions& options, float verticalExaggeration);

// FNV-1a, 64 bit.
std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t seed = 0xcbf29ce484222325ULL);

}  // namespace ensil::prep

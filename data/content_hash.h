// A fast hash of a file's bytes (xxHash's XXH3, 64 bits), for the identity of input data: the
// mesh cache key holds it, so a file whose contents changed never hits an old entry, even when
// its size and modification time were kept. Reads the whole file (GB/s); any thread.
#pragma once

#include <cstdint>
#include <string>

namespace ensil::data {

// Throws data::Error(FileNotFound) when the file cannot be read.
std::uint64_t contentHash(const std::string& path);

}  // namespace ensil::data

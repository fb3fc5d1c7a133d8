// A fast hash of a file's bytes (xxHash's XXH3, 64 bits), for the identity of input data: the
// mesh cache key holds it, so a file whose contents changed never hits an old entry, even when
// its size and modification time were kept. Reads the whole file (GB/s); any thread.
//
// Every time step of a file asks for the file's identity, and a forecast file of 10 steps is a
// gigabyte: hashing it again at every step cost about 140 ms of each new step. So the hash of a
// file is remembered in the process with the file's state (device, inode, size, modification
// and change times) and given again while that state is unchanged. The change time (ctime) moves
// on every write and cannot be set back by any tool (unlike the modification time, which rsync
// -t or touch put back), so an unchanged state means unchanged contents, with one exception the
// rule below closes: file times come from a clock that ticks every few milliseconds, so a write
// within the same tick as the last one could keep the change time. Only a file whose change time
// is over a second old when it is hashed is remembered; any later write then gets a later one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace ensil::data {

// Throws data::Error(FileNotFound) when the file cannot be read.
std::uint64_t contentHash(const std::string& path);

// How many times contentHash has read a whole file in this process (a hash given again from
// memory does not count): for tests and benchmarks.
std::size_t contentHashFileReads();

}  // namespace ensil::data

// A member's pass-2 result (mesh, statistics, distance to the mean) as bytes, for sending from a
// rank to rank 0, and back. Same machine architecture on every rank (as MPI_BYTE assumes).
#pragma once

#include <span>
#include <vector>

#include "preprocessing/streaming_preprocess.h"

namespace ensil::mpi {

std::vector<char> serialiseMember(const prep::MemberResult& result);

// Throws data::Error(CorruptFile) when the bytes are not one serialiseMember() made.
prep::MemberResult deserialiseMember(std::span<const char> bytes);

}  // namespace ensil::mpi

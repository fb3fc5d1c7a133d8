// The marching cubes case table, derived rather than typed in (see marching_cubes.h).
// Corner c of a cell sits at offset (c & 1, (c >> 1) & 1, (c >> 2) & 1). Edge e runs along axis
// e / 4 from corner kEdgeCorner[e]. Internal to preprocessing/.
#pragma once

#include <array>
#include <cstdint>

namespace ensil::prep::mc {

// For each of the 256 inside-masks: triangles as triples of edge ids, -1 terminated.
struct CaseTable {
    std::array<std::array<std::int8_t, 37>, 256> triangles{};
};

const CaseTable& caseTable();

// The lower corner of each edge (the one with the edge's axis bit clear).
extern const std::array<int, 12> kEdgeCorner;
inline int edgeAxis(int edge) { return edge / 4; }

}  // namespace ensil::prep::mc

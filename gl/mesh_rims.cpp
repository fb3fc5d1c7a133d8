#include "gl/mesh_rims.h"

#include <algorithm>
#include <array>

namespace ensil::gl {
namespace {
constexpr std::uint16_t kLowest = 0, kHighest = 65535;

// Bit 2a: on the low face of axis a; bit 2a + 1: on the high face.
unsigned facesOf(const data::PackedVertex& v, const std::array<bool, 6>& meshReaches) {
    unsigned faces = 0;
    for (int a = 0; a < 3; ++a) {
        if (meshReaches[2 * a] && v.position[a] == kLowest) faces |= 1U << (2 * a);
        if (meshReaches[2 * a + 1] && v.position[a] == kHighest) faces |= 1U << (2 * a + 1);
    }
    return faces;
}
}  // namespace

std::vector<std::uint32_t> rimSegments(const data::PackedMesh& mesh, const glm::vec3& gridLast) {
    std::vector<std::uint32_t> segments;
    // An isosurface needs two points along every axis; a smaller (or no) grid has no box.
    if (gridLast.x < 1.0F || gridLast.y < 1.0F || gridLast.z < 1.0F) return segments;
    // A coordinate lies on a face only when the mesh's bounds reach that face.
    std::array<bool, 6> reaches{};
    for (int a = 0; a < 3; ++a) {
        reaches[2 * a] = mesh.boundsMin[a] <= 0.0F;
        reaches[2 * a + 1] = mesh.boundsMax[a] >= gridLast[a];
    }
    bool any = false;
    for (const bool r : reaches) any = any || r;
    if (!any) return segments;
    std::vector<unsigned> faces(mesh.vertices.size());
    for (std::size_t v = 0; v < faces.size(); ++v) faces[v] = facesOf(mesh.vertices[v], reaches);
    // Edges with both ends on one face, as (smaller, larger) index pairs in one 64-bit key.
    std::vector<std::uint64_t> onFace;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = mesh.indices[t + e], b = mesh.indices[t + (e + 1) % 3];
            if (a < faces.size() && b < faces.size() && (faces[a] & faces[b]) != 0) {
                onFace.push_back((std::uint64_t{std::min(a, b)} << 32) | std::max(a, b));
            }
        }
    }
    // Decimation joins border vertices across the inside of a surface too: such an edge has a
    // triangle on either side, so it is found twice. Only an edge of one triangle is a rim.
    std::sort(onFace.begin(), onFace.end());
    for (std::size_t i = 0; i < onFace.size();) {
        std::size_t j = i + 1;
        while (j < onFace.size() && onFace[j] == onFace[i]) ++j;
        if (j == i + 1) {
            segments.push_back(static_cast<std::uint32_t>(onFace[i] >> 32));
            segments.push_back(static_cast<std::uint32_t>(onFace[i] & 0xFFFFFFFFU));
        }
        i = j;
    }
    return segments;
}

}  // namespace ensil::gl

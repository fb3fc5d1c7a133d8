// An indexed triangle mesh with shared vertices. Isosurface meshes keep their positions in the
// grid's index space (fractional grid indices: x in [0, nx-1] ...), so one mesh serves every
// mapping to display space (axis coordinates, log-pressure, vertical exaggeration). Triangles
// wind counter-clockwise seen from the side the surface normal n = -grad f / |grad f| points
// to, i.e. from the lower values. A value type; share read-only between threads.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace ensil::data {

struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;  // three per triangle

    [[nodiscard]] std::size_t vertexCount() const { return positions.size(); }
    [[nodiscard]] std::size_t triangleCount() const { return indices.size() / 3; }
    [[nodiscard]] bool empty() const { return indices.empty(); }
};

}  // namespace ensil::data

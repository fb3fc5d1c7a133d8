// The GPU format of an isosurface mesh: 20 bytes a vertex, as in the paper, with better
// encodings (algorithms.md section 3). Every field is a vertex format OpenGL 4.1 converts in
// hardware, so the vertex shader reads floats without unpacking code:
//   position      3 x uint16, normalised within the mesh's bounds in index space (6 bytes)
//   kappa1,kappa2 2 x IEEE half (4 bytes)
//   outlyingness  1 x IEEE half of o / outlyingnessScale (2 bytes)
//   normal        octahedral, 2 x snorm16 (4 bytes)
//   direction     octahedral, 2 x snorm16: the first principal curvature direction (4 bytes)
// Worst-case errors (checked by tests): position half a step of 1/65535 of the bounds per
// axis; unit vectors 2e-4 rad; halves 2^-11 relative within their range (|x| <= 65504,
// larger values clamp). A value type; any thread.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "data/triangle_mesh.h"
#include "preprocessing/vertex_attributes.h"

namespace ensil::prep {

struct PackedVertex {
    std::uint16_t position[3];
    std::uint16_t kappa1;
    std::uint16_t kappa2;
    std::uint16_t outlyingness;
    std::int16_t normal[2];
    std::int16_t direction[2];
};
static_assert(sizeof(PackedVertex) == 20, "the packed vertex must stay 20 bytes");

struct PackedMesh {
    std::vector<PackedVertex> vertices;
    std::vector<std::uint32_t> indices;
    glm::vec3 boundsMin{0.0F};  // index space
    glm::vec3 boundsMax{0.0F};
    float outlyingnessScale = 1.0F;  // stored outlyingness times this is the real value

    [[nodiscard]] std::size_t gpuBytes() const {
        return vertices.size() * sizeof(PackedVertex) + indices.size() * sizeof(std::uint32_t);
    }
};

PackedMesh packMesh(const data::TriangleMesh& mesh, const VertexAttributes& attributes);

// Decoders: what the vertex shader computes. For tests and CPU-side picking.
glm::vec3 unpackPosition(const PackedMesh& mesh, const PackedVertex& v);
float unpackHalf(std::uint16_t h);
std::uint16_t packHalf(float f);
glm::vec2 octahedralEncode(const glm::vec3& unit);  // into [-1, 1]^2
glm::vec3 octahedralDecode(glm::vec2 e);
glm::vec3 unpackUnitVector(const std::int16_t e[2]);

}  // namespace ensil::prep

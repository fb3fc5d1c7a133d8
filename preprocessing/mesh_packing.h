// Packs meshes and their attributes into the 20-byte GPU vertex of data/packed_mesh.h, and
// decodes it again (what the vertex shader does) for tests and CPU-side picking.
// Worst-case errors (checked by tests): position half a step of 1/65535 of the bounds per
// axis; unit vectors 2e-4 rad; halves 2^-11 relative within their range (|x| <= 65504,
// larger values clamp). A value type; any thread.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "data/packed_mesh.h"
#include "data/triangle_mesh.h"
#include "preprocessing/vertex_attributes.h"

namespace ensil::prep {

data::PackedMesh packMesh(const data::TriangleMesh& mesh, const VertexAttributes& attributes);

// Decoders: what the vertex shader computes. For tests and CPU-side picking.
glm::vec3 unpackPosition(const data::PackedMesh& mesh, const data::PackedVertex& v);
float unpackHalf(std::uint16_t h);
std::uint16_t packHalf(float f);
glm::vec2 octahedralEncode(const glm::vec3& unit);  // into [-1, 1]^2
glm::vec3 octahedralDecode(glm::vec2 e);
glm::vec3 unpackUnitVector(const std::int16_t e[2]);

// The largest outlyingness stored in any member's mesh (0 for none): the top of the range the
// density-based removal thresholds are chosen from.
float maximumOutlyingness(const data::MeshSet& meshes);

}  // namespace ensil::prep

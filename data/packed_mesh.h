// The GPU format of an isosurface mesh, 20 bytes a vertex (METHODS.md section 6). Every
// field is a vertex format OpenGL 4.1 converts in hardware:
//   position      3 x uint16, normalised within the mesh's bounds in grid index space
//   kappa1,kappa2 2 x IEEE half
//   outlyingness  1 x IEEE half of o / outlyingnessScale
//   normal        octahedral, 2 x snorm16
//   direction     octahedral, 2 x snorm16: the first principal curvature direction
// Produced by preprocessing (prep::packMesh), uploaded by gl. A value type; any thread.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace ensil::data {

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

// The meshes of one isovalue as the renderer takes them: every member's and the mean's.
struct MeshSet {
    float isovalue = 0.0F;
    std::vector<PackedMesh> members;  // one per member, in member order (may be empty meshes)
    PackedMesh mean;
    // The ensemble's summaries as context (METHODS.md section 17; empty when not built): the
    // surface where half the members exceed the isovalue, the two surfaces bounding the
    // contour boxplot's 50 % band, its median member (-1: none) and its outliers.
    PackedMesh probability;
    PackedMesh bandInner;
    PackedMesh bandOuter;
    int median = -1;
    std::vector<int> outliers;

    // Bytes on the GPU: every mesh's.
    [[nodiscard]] std::size_t gpuBytes() const {
        std::size_t bytes =
            mean.gpuBytes() + probability.gpuBytes() + bandInner.gpuBytes() + bandOuter.gpuBytes();
        for (const PackedMesh& m : members) bytes += m.gpuBytes();
        return bytes;
    }
};

}  // namespace ensil::data

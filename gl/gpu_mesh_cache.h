// GPU copies of the packed meshes of one isovalue: a vertex array with the 20-byte vertex
// layout (data/packed_mesh.h) and an index buffer per mesh. GUI thread, with the owning
// context current; release() before the context goes.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "data/packed_mesh.h"
#include "gl/gl_functions.h"

namespace ensil::gl {

struct GpuMesh {
    GLuint vao = 0, vertices = 0, indices = 0;
    GLsizei indexCount = 0;
    // The rims where the surface meets the box (gl/mesh_rims.h): GL_LINES over the same
    // vertices, position only.
    GLuint rimVao = 0, rimIndices = 0;
    GLsizei rimIndexCount = 0;
    glm::vec3 boundsMin{0.0F}, boundsMax{0.0F};
    float outlyingnessScale = 1.0F;
};

class GpuMeshCache {
public:
    // gridLast: the last grid index along each axis, the box whose faces hold the rims.
    void upload(GlFunctions& f, const data::MeshSet& meshes, const glm::vec3& gridLast);
    void release(GlFunctions& f);

    [[nodiscard]] const std::vector<GpuMesh>& members() const { return m_members; }
    [[nodiscard]] const GpuMesh& mean() const { return m_mean; }
    // The summaries (data::MeshSet): P(f > c) = 0.5 and the band's two bounding surfaces.
    [[nodiscard]] const GpuMesh& probability() const { return m_probability; }
    [[nodiscard]] const GpuMesh& bandInner() const { return m_bandInner; }
    [[nodiscard]] const GpuMesh& bandOuter() const { return m_bandOuter; }
    [[nodiscard]] std::size_t bytes() const { return m_bytes; }

private:
    GpuMesh uploadOne(GlFunctions& f, const data::PackedMesh& mesh, const glm::vec3& gridLast);

    std::vector<GpuMesh> m_members;
    GpuMesh m_mean, m_probability, m_bandInner, m_bandOuter;
    std::size_t m_bytes = 0;
};

}  // namespace ensil::gl

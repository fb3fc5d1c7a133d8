#include "gl/gpu_mesh_cache.h"

#include <array>
#include <cstddef>

#include "gl/mesh_rims.h"

namespace ensil::gl {
namespace {
// OpenGL takes buffer offsets as pointers.
const void* offset(std::size_t bytes) {
    return reinterpret_cast<const void*>(bytes);  // NOLINT(performance-no-int-to-ptr)
}

void releaseOne(GlFunctions& f, GpuMesh& m) {
    if (m.vao != 0) f.glDeleteVertexArrays(1, &m.vao);
    if (m.vertices != 0) f.glDeleteBuffers(1, &m.vertices);
    if (m.indices != 0) f.glDeleteBuffers(1, &m.indices);
    if (m.rimVao != 0) f.glDeleteVertexArrays(1, &m.rimVao);
    if (m.rimIndices != 0) f.glDeleteBuffers(1, &m.rimIndices);
    m = GpuMesh{};
}
}  // namespace

GpuMesh GpuMeshCache::uploadOne(GlFunctions& f, const data::PackedMesh& mesh,
                                const glm::vec3& gridLast) {
    GpuMesh g;
    g.boundsMin = mesh.boundsMin;
    g.boundsMax = mesh.boundsMax;
    g.outlyingnessScale = mesh.outlyingnessScale;
    g.indexCount = static_cast<GLsizei>(mesh.indices.size());
    if (mesh.vertices.empty()) return g;
    f.glGenVertexArrays(1, &g.vao);
    f.glBindVertexArray(g.vao);
    f.glGenBuffers(1, &g.vertices);
    f.glBindBuffer(GL_ARRAY_BUFFER, g.vertices);
    f.glBufferData(GL_ARRAY_BUFFER,
                   static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(data::PackedVertex)),
                   mesh.vertices.data(), GL_STATIC_DRAW);
    f.glGenBuffers(1, &g.indices);
    f.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices);
    f.glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                   static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                   mesh.indices.data(), GL_STATIC_DRAW);
    // The 20-byte layout of data/packed_mesh.h, one attribute per field; the GL converts.
    struct Attribute {
        GLint size;
        GLenum type;
        GLboolean normalized;
        std::size_t offset;
    };
    const std::array<Attribute, 5> layout{{
        {3, GL_UNSIGNED_SHORT, GL_TRUE, offsetof(data::PackedVertex, position)},
        {2, GL_HALF_FLOAT, GL_FALSE, offsetof(data::PackedVertex, kappa1)},
        {1, GL_HALF_FLOAT, GL_FALSE, offsetof(data::PackedVertex, outlyingness)},
        {2, GL_SHORT, GL_TRUE, offsetof(data::PackedVertex, normal)},
        {2, GL_SHORT, GL_TRUE, offsetof(data::PackedVertex, direction)},
    }};
    constexpr auto stride = static_cast<GLsizei>(sizeof(data::PackedVertex));
    for (GLuint location = 0; location < layout.size(); ++location) {
        const Attribute& a = layout[location];
        f.glEnableVertexAttribArray(location);
        f.glVertexAttribPointer(location, a.size, a.type, a.normalized, stride, offset(a.offset));
    }
    f.glBindVertexArray(0);
    m_bytes += mesh.vertices.size() * sizeof(data::PackedVertex) +
               mesh.indices.size() * sizeof(std::uint32_t);

    const std::vector<std::uint32_t> rims = rimSegments(mesh, gridLast);
    if (rims.empty()) return g;
    g.rimIndexCount = static_cast<GLsizei>(rims.size());
    f.glGenVertexArrays(1, &g.rimVao);
    f.glBindVertexArray(g.rimVao);
    f.glBindBuffer(GL_ARRAY_BUFFER, g.vertices);
    f.glGenBuffers(1, &g.rimIndices);
    f.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.rimIndices);
    f.glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                   static_cast<GLsizeiptr>(rims.size() * sizeof(std::uint32_t)), rims.data(),
                   GL_STATIC_DRAW);
    const Attribute& position = layout[0];
    f.glEnableVertexAttribArray(0);
    f.glVertexAttribPointer(0, position.size, position.type, position.normalized, stride,
                            offset(position.offset));
    f.glBindVertexArray(0);
    m_bytes += rims.size() * sizeof(std::uint32_t);
    return g;
}

void GpuMeshCache::upload(GlFunctions& f, const data::MeshSet& meshes, const glm::vec3& gridLast) {
    release(f);
    m_members.reserve(meshes.members.size());
    for (const data::PackedMesh& m : meshes.members) {
        m_members.push_back(uploadOne(f, m, gridLast));
    }
    m_mean = uploadOne(f, meshes.mean, gridLast);
    m_probability = uploadOne(f, meshes.probability, gridLast);
    m_bandInner = uploadOne(f, meshes.bandInner, gridLast);
    m_bandOuter = uploadOne(f, meshes.bandOuter, gridLast);
}

void GpuMeshCache::release(GlFunctions& f) {
    for (GpuMesh& m : m_members) releaseOne(f, m);
    m_members.clear();
    for (GpuMesh* m : {&m_mean, &m_probability, &m_bandInner, &m_bandOuter}) releaseOne(f, *m);
    m_bytes = 0;
}

}  // namespace ensil::gl

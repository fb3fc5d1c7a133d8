#include "gl/gpu_mesh_cache.h"

#include <cstddef>

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
    m = GpuMesh{};
}
}  // namespace

GpuMesh GpuMeshCache::uploadOne(GlFunctions& f, const data::PackedMesh& mesh) {
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
    constexpr auto stride = static_cast<GLsizei>(sizeof(data::PackedVertex));
    f.glEnableVertexAttribArray(0);
    f.glVertexAttribPointer(0, 3, GL_UNSIGNED_SHORT, GL_TRUE, stride,
                            offset(offsetof(data::PackedVertex, position)));
    f.glEnableVertexAttribArray(1);
    f.glVertexAttribPointer(1, 2, GL_HALF_FLOAT, GL_FALSE, stride,
                            offset(offsetof(data::PackedVertex, kappa1)));
    f.glEnableVertexAttribArray(2);
    f.glVertexAttribPointer(2, 1, GL_HALF_FLOAT, GL_FALSE, stride,
                            offset(offsetof(data::PackedVertex, outlyingness)));
    f.glEnableVertexAttribArray(3);
    f.glVertexAttribPointer(3, 2, GL_SHORT, GL_TRUE, stride,
                            offset(offsetof(data::PackedVertex, normal)));
    f.glEnableVertexAttribArray(4);
    f.glVertexAttribPointer(4, 2, GL_SHORT, GL_TRUE, stride,
                            offset(offsetof(data::PackedVertex, direction)));
    f.glBindVertexArray(0);
    m_bytes += mesh.vertices.size() * sizeof(data::PackedVertex) +
               mesh.indices.size() * sizeof(std::uint32_t);
    return g;
}

void GpuMeshCache::upload(GlFunctions& f, const data::MeshSet& meshes) {
    release(f);
    m_members.reserve(meshes.members.size());
    for (const data::PackedMesh& m : meshes.members) m_members.push_back(uploadOne(f, m));
    m_mean = uploadOne(f, meshes.mean);
}

void GpuMeshCache::release(GlFunctions& f) {
    for (GpuMesh& m : m_members) releaseOne(f, m);
    m_members.clear();
    releaseOne(f, m_mean);
    m_bytes = 0;
}

}  // namespace ensil::gl

#include "mpi/mesh_transfer.h"

#include <cstdint>
#include <cstring>
#include <type_traits>

#include "data/error.h"

namespace ensil::mpi {
namespace {

// Everything of a MemberResult but its two arrays.
struct Header {
    std::uint64_t vertices = 0, indices = 0;
    float boundsMin[3]{}, boundsMax[3]{};
    float outlyingnessScale = 1.0F;
    float error = 0.0F;
    double seconds[3]{};
    std::uint64_t extracted = 0, triangles = 0, meshVertices = 0;
    double distanceToMean = 0.0;
};
static_assert(std::is_trivially_copyable_v<Header>);
static_assert(std::is_trivially_copyable_v<data::PackedVertex>);

}  // namespace

std::vector<char> serialiseMember(const prep::MemberResult& r) {
    const data::PackedMesh& mesh = r.meshed.mesh;
    const prep::FieldMeshStats& s = r.meshed.stats;
    Header h;
    h.vertices = mesh.vertices.size();
    h.indices = mesh.indices.size();
    for (int a = 0; a < 3; ++a) {
        h.boundsMin[a] = mesh.boundsMin[a];
        h.boundsMax[a] = mesh.boundsMax[a];
    }
    h.outlyingnessScale = mesh.outlyingnessScale;
    h.error = s.error;
    h.seconds[0] = s.seconds.meshes;
    h.seconds[1] = s.seconds.decimation;
    h.seconds[2] = s.seconds.attributes;
    h.extracted = s.extracted;
    h.triangles = s.triangles;
    h.meshVertices = s.vertices;
    h.distanceToMean = r.distanceToMean;
    const std::size_t vertexBytes = mesh.vertices.size() * sizeof(data::PackedVertex);
    const std::size_t indexBytes = mesh.indices.size() * sizeof(std::uint32_t);
    std::vector<char> bytes(sizeof h + vertexBytes + indexBytes);
    std::memcpy(bytes.data(), &h, sizeof h);
    if (vertexBytes > 0) std::memcpy(bytes.data() + sizeof h, mesh.vertices.data(), vertexBytes);
    if (indexBytes > 0) {
        std::memcpy(bytes.data() + sizeof h + vertexBytes, mesh.indices.data(), indexBytes);
    }
    return bytes;
}

prep::MemberResult deserialiseMember(std::span<const char> bytes) {
    Header h;
    if (bytes.size() < sizeof h) {
        throw data::Error(data::ErrorKind::CorruptFile,
                          "a rank sent " + std::to_string(bytes.size()) +
                              " bytes for a member's mesh, fewer than its header");
    }
    std::memcpy(&h, bytes.data(), sizeof h);
    const std::size_t vertexBytes = h.vertices * sizeof(data::PackedVertex);
    const std::size_t indexBytes = h.indices * sizeof(std::uint32_t);
    if (h.vertices > bytes.size() || h.indices > bytes.size() ||
        bytes.size() != sizeof h + vertexBytes + indexBytes) {
        throw data::Error(data::ErrorKind::CorruptFile,
                          "a rank sent " + std::to_string(bytes.size()) +
                              " bytes for a member's mesh that says it has " +
                              std::to_string(h.vertices) + " vertices and " +
                              std::to_string(h.indices) + " indices");
    }
    prep::MemberResult r;
    data::PackedMesh& mesh = r.meshed.mesh;
    mesh.vertices.resize(h.vertices);
    mesh.indices.resize(h.indices);
    if (vertexBytes > 0) std::memcpy(mesh.vertices.data(), bytes.data() + sizeof h, vertexBytes);
    if (indexBytes > 0) {
        std::memcpy(mesh.indices.data(), bytes.data() + sizeof h + vertexBytes, indexBytes);
    }
    for (int a = 0; a < 3; ++a) {
        mesh.boundsMin[a] = h.boundsMin[a];
        mesh.boundsMax[a] = h.boundsMax[a];
    }
    mesh.outlyingnessScale = h.outlyingnessScale;
    prep::FieldMeshStats& s = r.meshed.stats;
    s.error = h.error;
    s.seconds = {h.seconds[0], h.seconds[1], h.seconds[2]};
    s.extracted = h.extracted;
    s.triangles = h.triangles;
    s.vertices = h.meshVertices;
    r.distanceToMean = h.distanceToMean;
    return r;
}

}  // namespace ensil::mpi

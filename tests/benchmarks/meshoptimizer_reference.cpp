#include "meshoptimizer_reference.h"

#include <meshoptimizer.h>

ReferenceSimplification simplifyWithMeshoptimizer(const ensil::data::TriangleMesh& mesh,
                                                  float maxErrorCells) {
    ReferenceSimplification result;
    const auto* positions = &mesh.positions.front().x;
    const std::size_t stride = sizeof(glm::vec3);
    // meshoptimizer's error is relative to the mesh's extent.
    const float scale = meshopt_simplifyScale(positions, mesh.vertexCount(), stride);
    std::vector<std::uint32_t> kept(mesh.indices.size());
    float relativeError = 0.0F;
    // Target zero triangles: the error bound alone decides where to stop.
    kept.resize(meshopt_simplify(kept.data(), mesh.indices.data(), mesh.indices.size(), positions,
                                 mesh.vertexCount(), stride, 0, maxErrorCells / scale,
                                 meshopt_SimplifyLockBorder, &relativeError));
    result.mesh.positions = mesh.positions;
    result.mesh.indices = std::move(kept);
    result.errorCells = relativeError * scale;
    return result;
}

#include "preprocessing/decimation.h"

#include <meshoptimizer.h>

namespace ensil::prep {

DecimationResult decimateMesh(const data::TriangleMesh& mesh, float maxErrorCells) {
    DecimationResult result;
    if (mesh.empty()) return result;
    const auto* positions = reinterpret_cast<const float*>(mesh.positions.data());
    const std::size_t stride = sizeof(glm::vec3);
    std::vector<std::uint32_t> indices = mesh.indices;
    if (maxErrorCells > 0.0F) {
        const float scale = meshopt_simplifyScale(positions, mesh.vertexCount(), stride);
        float relativeError = 0.0F;
        std::vector<std::uint32_t> simplified(indices.size());
        // Target zero triangles: the error bound alone decides where to stop.
        const std::size_t count = meshopt_simplify(
            simplified.data(), indices.data(), indices.size(), positions, mesh.vertexCount(),
            stride, 0, maxErrorCells / scale, meshopt_SimplifyLockBorder, &relativeError);
        simplified.resize(count);
        indices = std::move(simplified);
        result.errorCells = relativeError * scale;
    }
    meshopt_optimizeVertexCache(indices.data(), indices.data(), indices.size(), mesh.vertexCount());
    result.mesh.positions.resize(mesh.vertexCount());
    const std::size_t kept =
        meshopt_optimizeVertexFetch(result.mesh.positions.data(), indices.data(), indices.size(),
                                    mesh.positions.data(), mesh.vertexCount(), stride);
    result.mesh.positions.resize(kept);
    result.mesh.indices = std::move(indices);
    return result;
}

}  // namespace ensil::prep

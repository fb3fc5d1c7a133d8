#include "preprocessing/decimation.h"

#include <meshoptimizer.h>

#include "preprocessing/quadric_simplification.h"

namespace ensil::prep {

DecimationResult decimateMesh(data::TriangleMesh mesh, float maxErrorCells) {
    DecimationResult result;
    if (mesh.empty()) return result;
    SimplifiedMesh simplified = simplifyMesh(std::move(mesh), maxErrorCells);
    result.errorCells = simplified.error;
    std::vector<std::uint32_t> indices = std::move(simplified.mesh.indices);
    const std::vector<glm::vec3>& positions = simplified.mesh.positions;
    meshopt_optimizeVertexCache(indices.data(), indices.data(), indices.size(), positions.size());
    result.mesh.positions.resize(positions.size());
    const std::size_t kept =
        meshopt_optimizeVertexFetch(result.mesh.positions.data(), indices.data(), indices.size(),
                                    positions.data(), positions.size(), sizeof(glm::vec3));
    result.mesh.positions.resize(kept);
    result.mesh.indices = std::move(indices);
    return result;
}

}  // namespace ensil::prep

// Mesh decimation by quadric error metrics (Garland & Heckbert 1997; quadric_simplification.h),
// under an error bound given in grid cells, so that it means the same on every data set (mesh
// positions are in index space, where one cell is one unit). Vertices on the mesh's open
// border (where the surface leaves the volume or meets missing data) stay put, so decimated
// neighbours still meet. The result is compacted and reordered for the GPU's vertex cache
// (meshoptimizer). Pure function; any thread.
#pragma once

#include "data/triangle_mesh.h"

namespace ensil::prep {

struct DecimationResult {
    data::TriangleMesh mesh;
    float errorCells = 0.0F;  // the simplification's error (SimplifiedMesh::error), in cells
};

// maxErrorCells <= 0 returns the mesh unchanged (but cache-optimised). By value, as
// simplifyMesh: hand the mesh over with std::move when it is not needed afterwards.
DecimationResult decimateMesh(data::TriangleMesh mesh, float maxErrorCells);

}  // namespace ensil::prep

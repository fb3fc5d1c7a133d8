// Mesh decimation by quadric error metrics (Garland & Heckbert 1997) with meshoptimizer, under
// an error bound given in grid cells, so that it means the same on every data set (mesh
// positions are in index space, where one cell is one unit). Vertices on the mesh's open
// border (where the surface leaves the volume or meets missing data) stay put, so decimated
// neighbours still meet. The result is compacted and reordered for the GPU's vertex cache.
// Chosen over OpenMesh's Decimater by measurement: about 40x faster at similar error (see the
// preprocessing benchmark). Pure function; any thread.
#pragma once

#include "data/triangle_mesh.h"

namespace ensil::prep {

struct DecimationResult {
    data::TriangleMesh mesh;
    float errorCells = 0.0F;  // meshoptimizer's own estimate of the geometric error, in cells
};

// maxErrorCells <= 0 returns the mesh unchanged (but cache-optimised).
DecimationResult decimateMesh(const data::TriangleMesh& mesh, float maxErrorCells);

}  // namespace ensil::prep

// meshoptimizer's simplifier (meshopt_simplify, 0.18 from Debian) under the same error bound as
// ensil's decimation, borders locked as ensil's: the reference that ensil's own simplification
// (preprocessing/quadric_simplification.h) is measured against. Benchmarks only.
#pragma once

#include "data/triangle_mesh.h"

struct ReferenceSimplification {
    ensil::data::TriangleMesh mesh;  // the input's vertices, the kept triangles
    float errorCells = 0.0F;         // meshoptimizer's own estimate, in cells
};

ReferenceSimplification simplifyWithMeshoptimizer(const ensil::data::TriangleMesh& mesh,
                                                  float maxErrorCells);

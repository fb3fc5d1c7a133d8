// One-sided Hausdorff distance from a mesh's vertices to another mesh's surface (largest and
// mean of the point-to-triangle distances), with a uniform grid of buckets over the target's
// triangles. For reporting decimation quality in the benchmark.
#pragma once

#include "data/triangle_mesh.h"

struct SurfaceDistance {
    double maximum = 0.0, mean = 0.0;
};

SurfaceDistance distanceToSurface(const ensil::data::TriangleMesh& from,
                                  const ensil::data::TriangleMesh& to);

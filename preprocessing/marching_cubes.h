// Marching cubes (Lorensen & Cline) producing an indexed, watertight mesh: vertices sit on
// grid edges and are shared by every cell around the edge, so the surface is closed wherever
// it does not leave the volume. The case table is derived at start-up from one rule, "on each
// cube face, inside corners (value > isovalue) that touch only diagonally stay separated",
// which depends only on the face, so neighbouring cells always agree: no cracks, consistent
// orientation. Cells touching a missing value (NaN) make no triangles.
// Positions are in index space (see data/triangle_mesh.h). One pass over the values turns each
// grid row into bit sets (inside, valid); crossing edges and the cells that make triangles are
// then found 64 points at a time, so empty regions cost next to nothing and no grid-sized
// arrays are allocated. The work is parallel over z-layers (oneTBB), which composes with
// parallelism over members; the result does not depend on the thread count. Pure function;
// any thread.
#pragma once

#include <span>
#include <stop_token>

#include "data/grid.h"
#include "data/job.h"
#include "data/triangle_mesh.h"

namespace ensil::prep {

// values: grid.pointCount() values, x fastest. Throws data::Cancelled.
data::TriangleMesh extractIsosurface(const data::Grid& grid, std::span<const float> values,
                                     float isovalue, const std::stop_token& stop = {},
                                     const data::Progress& progress = {});

}  // namespace ensil::prep

// The rims of an isosurface: the segments where it meets a face of the data box. A surface that
// leaves the box has no silhouette there, and on data with few levels (ERA5's two pressure
// levels) the isosurface is a sheet whose only telling outline is its rim on the top and bottom
// faces: there it is the member's contour line at that level, the meteorologist's spaghetti
// plot. METHODS.md section 9. Pure function; any thread.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "data/packed_mesh.h"

namespace ensil::gl {

// Index pairs (GL_LINES into mesh.vertices) of the edges of exactly one triangle whose two ends
// lie on the same face of the box [0, gridLast] in grid index space. Marching cubes puts a
// vertex on a face exactly, decimation keeps border vertices in place, and the packing keeps a
// coordinate at the mesh's bounds exact (code 0 or 65535), so the test is exact. An edge of two
// triangles lies inside the surface (decimation joins border vertices across it), not on its
// rim. Each rim segment appears once.
std::vector<std::uint32_t> rimSegments(const data::PackedMesh& mesh, const glm::vec3& gridLast);

}  // namespace ensil::gl

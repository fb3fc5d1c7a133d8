// Mesh simplification by half-edge collapses under quadric error metrics (Garland & Heckbert
// 1997), under an error bound in the mesh's own units (grid cells for isosurfaces). A vertex
// moves onto a neighbour, so no new positions are made; vertices on an open border stay put;
// a collapse that would fold a triangle over or join two parts of the surface (the link
// condition) is refused, so a closed manifold mesh stays closed and manifold.
//
// Ours rather than meshoptimizer's meshopt_simplify (Debian ships 0.18 only) because it is
// faster on marching-cubes meshes at the same error bound, with fewer triangles and a smaller
// largest distance between the surfaces; `ensil_preprocess_benchmark` prints both side by
// side. See METHODS.md section 2. Pure function; any thread.
#pragma once

#include "data/triangle_mesh.h"

namespace ensil::prep {

struct SimplifiedMesh {
    data::TriangleMesh mesh;  // the kept vertices, in their input order; the kept triangles
    // The largest error of any collapse made: the area-weighted root-mean-square distance of the
    // vertex's new position to the planes of the input triangles merged into it. <= the bound.
    float error = 0.0F;
};

// maxError <= 0 (or NaN) returns the mesh unchanged. The mesh is taken by value: handed over
// with std::move, its arrays become the working ones instead of being copied (a full-resolution
// mesh less in memory for every member being meshed).
SimplifiedMesh simplifyMesh(data::TriangleMesh mesh, float maxError);

}  // namespace ensil::prep

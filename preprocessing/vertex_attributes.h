// Per-vertex attributes for silhouette rendering (METHODS.md section 4), computed in display
// space, where the silhouette test happens: the normal, the principal curvatures kappa_1 >=
// kappa_2 and the first principal curvature direction (Kindlmann et al. 2003), and the
// member's outlyingness. Derivatives come from central differences on the grid (one-sided at
// the border and next to missing values), taken in display coordinates (so uneven levels,
// log-pressure and vertical exaggeration are accounted for), then interpolated trilinearly to
// the vertex. Because they come from the field, not from the mesh, they are as good on a
// decimated mesh as on the full one. Pure function; any thread.
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <span>
#include <stop_token>
#include <vector>

#include "data/display_frame.h"
#include "data/job.h"
#include "data/triangle_mesh.h"
#include "preprocessing/ensemble_moments.h"

namespace ensil::prep {

struct VertexAttributes {
    std::vector<glm::vec3> normals;  // n = -grad f / |grad f|, unit
    std::vector<float> kappa1;       // kappa1 >= kappa2; for f = |x - c| both are -1/r
    std::vector<float> kappa2;
    std::vector<glm::vec3> principalDirections;  // unit, tangent, for kappa1
    std::vector<float> outlyingness;             // 0 when no moments are given
};

// Display coordinates of every grid index along x, y and z (DisplayFrame::axisTable).
using AxisTables = std::array<std::vector<double>, 3>;
AxisTables axisTables(const data::DisplayFrame& frame);

// mesh positions are in index space; values is the member's field. Throws data::Cancelled.
VertexAttributes computeVertexAttributes(const data::Grid& grid, std::span<const float> values,
                                         const data::TriangleMesh& mesh, const AxisTables& axes,
                                         float isovalue, const EnsembleMoments* moments = nullptr,
                                         const std::stop_token& stop = {});

}  // namespace ensil::prep

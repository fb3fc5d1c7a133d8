// The same per-member work done with VTK 9's own filters, as a reference for the speed-up:
// vtkFlyingEdges3D, vtkQuadricDecimation to the triangle count ensil reaches, vtkCurvatures.
#pragma once

#include <cstddef>

#include "data/ensemble.h"

struct VtkReferenceTimes {
    double isosurface = 0, decimation = 0, curvature = 0;
    std::size_t trianglesIn = 0, trianglesOut = 0;
};

// Seconds vtkFlyingEdges3D takes for the first `members` members at the isovalue (one after
// another; VTK's SMP backend runs each on all threads), and the triangles it made.
struct VtkIsosurfaceTime {
    double seconds = 0;
    std::size_t triangles = 0;
};
VtkIsosurfaceTime timeVtkFlyingEdges(const ensil::data::Ensemble& ensemble, float isovalue,
                                     std::size_t members);

// Processes `members` members (and nothing else) at the isovalue, reducing each to
// `targetTrianglesPerMember` triangles. Single-threaded per filter as VTK runs them here.
VtkReferenceTimes runVtkReference(const ensil::data::Ensemble& ensemble, float isovalue,
                                  std::size_t members, std::size_t targetTrianglesPerMember);

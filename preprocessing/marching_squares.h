// The contour lines of a 2D field at one level (marching squares): where each member's
// isosurface meets a map or a cross-section. Points are fractional lattice indices (u along
// columns, v along rows), linear between samples on each cell edge, so a section through grid
// points gives the same points as marching cubes gives on that face. A cell with a missing
// (NaN) corner has no line. The two saddle cases are told apart by the cell's centre, the mean
// of its corners (METHODS.md section 22). Pure; any thread.
#pragma once

#include <cstddef>
#include <glm/vec2.hpp>
#include <span>
#include <vector>

namespace ensil::prep {

struct ContourLine {
    std::vector<glm::dvec2> points;  // (column, row), fractional
    bool closed = false;             // the last point joins the first
};

// `values` holds columns x rows samples, column fastest. A value above `level` is inside.
// Throws data::Error(InvalidArgument) when the sizes disagree.
std::vector<ContourLine> contourLines(std::span<const float> values, std::size_t columns,
                                      std::size_t rows, float level);

}  // namespace ensil::prep

// A 2D section of a 3D field: a horizontal map at one (fractional) level, or a vertical
// cross-section along a path of horizontal points with every level. Samples are taken at
// fractional grid indices by trilinear interpolation (data/field_sampling.h), so a section
// through grid points holds the data's own values, and between levels it is linear in the
// level's index, as the isosurfaces are. Pure; any thread.
#pragma once

#include <cstddef>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "data/grid.h"

namespace ensil::prep {

// Where each sample of a section lies: columns x rows fractional grid indices, column fastest.
struct SectionLattice {
    std::size_t columns = 0;
    std::size_t rows = 0;
    std::vector<glm::dvec3> indices;
    // x runs round the globe: an x index between nx - 1 and nx lies in the cell that joins the
    // last column to the first (a longitude grid from 0 to 357 crossed at 358.5).
    bool wrapsX = false;
};

// Every horizontal grid point at level `zIndex` (from 0 to nz - 1): columns along x, rows
// along y. Throws data::Error(InvalidArgument) for a level outside the grid.
SectionLattice horizontalLattice(const data::Grid& grid, double zIndex);
// Every level under each of `path`'s points (fractional x, y indices inside the grid):
// columns along the path, rows up the z axis's index. Throws data::Error(InvalidArgument) for
// fewer than 2 points or a point outside the grid.
// With `wrapsX`, x indices up to nx (not nx - 1) are inside.
SectionLattice verticalLattice(const data::Grid& grid, const std::vector<glm::dvec2>& path,
                               bool wrapsX = false);

// The field's values at the lattice's samples (NaN where it has none).
std::vector<float> sampleSection(const data::Grid& grid, std::span<const float> values,
                                 const SectionLattice& lattice);

}  // namespace ensil::prep

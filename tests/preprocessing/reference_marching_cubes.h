// A plain marching cubes, cell by cell, as the tests' reference for the fast extraction: it
// visits every cell, skips those with a missing corner, and writes each triangle as three
// positions (no sharing), interpolated from each edge's lower point exactly as METHODS.md
// section 2 says. Slow and obviously right; tests only.
#pragma once

#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "data/grid.h"
#include "preprocessing/marching_cubes_table.h"

namespace ensil::test {

using Triangle = std::array<glm::vec3, 3>;

struct ReferenceSurface {
    std::vector<Triangle> triangles;
    std::size_t crossingEdges = 0;  // grid edges whose ends are valid and on different sides
};

inline ReferenceSurface referenceMarchingCubes(const data::Grid& grid, std::span<const float> f,
                                               float iso) {
    const std::size_t nx = grid.nx(), ny = grid.ny(), nz = grid.nz();
    const auto at = [&](std::size_t i, std::size_t j, std::size_t k) {
        return f[i + nx * (j + ny * k)];
    };
    ReferenceSurface out;
    for (std::size_t k = 0; k < nz; ++k)
        for (std::size_t j = 0; j < ny; ++j)
            for (std::size_t i = 0; i < nx; ++i) {
                const float a = at(i, j, k);
                const std::array<bool, 3> has{i + 1 < nx, j + 1 < ny, k + 1 < nz};
                for (int axis = 0; axis < 3; ++axis) {
                    if (!has[static_cast<std::size_t>(axis)]) continue;
                    const float b = at(i + (axis == 0), j + (axis == 1), k + (axis == 2));
                    if (!std::isnan(a) && !std::isnan(b) && ((a > iso) != (b > iso))) {
                        ++out.crossingEdges;
                    }
                }
            }
    const auto& table = prep::mc::caseTable();
    for (std::size_t k = 0; k + 1 < nz; ++k)
        for (std::size_t j = 0; j + 1 < ny; ++j)
            for (std::size_t i = 0; i + 1 < nx; ++i) {
                const auto corner = [&](int c) {
                    return at(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
                };
                std::size_t mask = 0;
                bool valid = true;
                for (int c = 0; c < 8; ++c) {
                    valid = valid && !std::isnan(corner(c));
                    if (corner(c) > iso) mask |= std::size_t{1} << c;
                }
                if (!valid) continue;
                const auto vertex = [&](int edge) {
                    const int c = prep::mc::kEdgeCorner[static_cast<std::size_t>(edge)];
                    const int axis = prep::mc::edgeAxis(edge);
                    const float p = corner(c), q = corner(c | (1 << axis));
                    glm::vec3 pos{static_cast<float>(i + (c & 1)),
                                  static_cast<float>(j + ((c >> 1) & 1)),
                                  static_cast<float>(k + ((c >> 2) & 1))};
                    pos[axis] += (iso - p) / (q - p);
                    return pos;
                };
                for (const std::int8_t* e = table.triangles[mask].data(); *e >= 0; e += 3) {
                    out.triangles.push_back({vertex(e[0]), vertex(e[1]), vertex(e[2])});
                }
            }
    return out;
}

}  // namespace ensil::test

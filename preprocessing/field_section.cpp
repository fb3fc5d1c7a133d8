#include "preprocessing/field_section.h"

#include <cmath>
#include <string>

#include "data/error.h"
#include "data/field_sampling.h"

namespace ensil::prep {
namespace {

bool within(double index, std::size_t n) {
    return std::isfinite(index) && index >= 0.0 && index <= static_cast<double>(n - 1);
}

}  // namespace

SectionLattice horizontalLattice(const data::Grid& grid, double zIndex) {
    if (!within(zIndex, grid.nz())) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "a map at level index " + std::to_string(zIndex) +
                              " lies outside the grid's " + std::to_string(grid.nz()) + " levels");
    }
    SectionLattice lattice{grid.nx(), grid.ny(), {}};
    lattice.indices.reserve(grid.nx() * grid.ny());
    for (std::size_t j = 0; j < grid.ny(); ++j) {
        for (std::size_t i = 0; i < grid.nx(); ++i) {
            lattice.indices.emplace_back(static_cast<double>(i), static_cast<double>(j), zIndex);
        }
    }
    return lattice;
}

SectionLattice verticalLattice(const data::Grid& grid, const std::vector<glm::dvec2>& path,
                               bool wrapsX) {
    if (path.size() < 2) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "a cross-section needs a path of at least 2 points");
    }
    for (const glm::dvec2& p : path) {
        if (!within(p.x, grid.nx() + (wrapsX ? 1 : 0)) || !within(p.y, grid.ny())) {
            throw data::Error(data::ErrorKind::InvalidArgument,
                              "a cross-section's point (" + std::to_string(p.x) + ", " +
                                  std::to_string(p.y) + ") lies outside the grid");
        }
    }
    SectionLattice lattice{path.size(), grid.nz(), {}, wrapsX};
    lattice.indices.reserve(path.size() * grid.nz());
    for (std::size_t k = 0; k < grid.nz(); ++k) {
        for (const glm::dvec2& p : path) lattice.indices.emplace_back(p, static_cast<double>(k));
    }
    return lattice;
}

std::vector<float> sampleSection(const data::Grid& grid, std::span<const float> values,
                                 const SectionLattice& lattice) {
    std::vector<float> section;
    section.reserve(lattice.indices.size());
    const auto last = static_cast<double>(grid.nx() - 1);
    for (const glm::dvec3& index : lattice.indices) {
        if (!lattice.wrapsX || index.x <= last) {
            section.push_back(data::sampleTrilinear(grid, values, index));
            continue;
        }
        // In the cell across the seam: linear between the last column and the first, as
        // trilinear interpolation is along x inside any other cell.
        const double f = index.x - last;
        const float a = data::sampleTrilinear(grid, values, {last, index.y, index.z});
        const float b = data::sampleTrilinear(grid, values, {0.0, index.y, index.z});
        section.push_back(std::isnan(a)   ? b
                          : std::isnan(b) ? a
                                          : static_cast<float>((1.0 - f) * a + f * b));
    }
    return section;
}

}  // namespace ensil::prep

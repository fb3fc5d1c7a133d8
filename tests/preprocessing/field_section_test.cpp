#include "preprocessing/field_section.h"

#include <gtest/gtest.h>

#include "data/error.h"

using namespace ensil;

namespace {

data::Grid smallGrid() {
    return data::Grid(data::makeUniformAxis("x", "m", 0.0, 4.0, 5),
                      data::makeUniformAxis("y", "m", 0.0, 3.0, 4),
                      data::makeUniformAxis("z", "m", 0.0, 2.0, 3));
}

// f = x + 10 y + 100 z at the grid points: linear, so any section of it is exact.
std::vector<float> linearField(const data::Grid& grid) {
    std::vector<float> values(grid.pointCount());
    for (std::size_t k = 0; k < grid.nz(); ++k) {
        for (std::size_t j = 0; j < grid.ny(); ++j) {
            for (std::size_t i = 0; i < grid.nx(); ++i) {
                values[grid.index(i, j, k)] = static_cast<float>(i + 10 * j + 100 * k);
            }
        }
    }
    return values;
}

}  // namespace

TEST(FieldSection, MapBetweenLevelsIsLinearInTheLevelIndex) {
    const data::Grid grid = smallGrid();
    const prep::SectionLattice lattice = prep::horizontalLattice(grid, 1.25);
    ASSERT_EQ(lattice.columns, 5U);
    ASSERT_EQ(lattice.rows, 4U);
    const std::vector<float> section = prep::sampleSection(grid, linearField(grid), lattice);
    ASSERT_EQ(section.size(), 20U);
    EXPECT_FLOAT_EQ(section[0], 125.0F);
    EXPECT_FLOAT_EQ(section[3 + 5 * 2], 3.0F + 20.0F + 125.0F);  // column 3, row 2
}

TEST(FieldSection, CrossSectionHasEveryLevelUnderEachPathPoint) {
    const data::Grid grid = smallGrid();
    const std::vector<glm::dvec2> path{{0.5, 1.0}, {2.0, 1.5}, {4.0, 3.0}};
    const prep::SectionLattice lattice = prep::verticalLattice(grid, path);
    ASSERT_EQ(lattice.columns, 3U);
    ASSERT_EQ(lattice.rows, 3U);
    const std::vector<float> section = prep::sampleSection(grid, linearField(grid), lattice);
    EXPECT_FLOAT_EQ(section[0], 0.5F + 10.0F);                   // column 0, level 0
    EXPECT_FLOAT_EQ(section[1 + 3 * 2], 2.0F + 15.0F + 200.0F);  // column 1, level 2
    EXPECT_FLOAT_EQ(section[2 + 3 * 1], 4.0F + 30.0F + 100.0F);
}

TEST(FieldSection, RefusesPlacesOutsideTheGrid) {
    const data::Grid grid = smallGrid();
    EXPECT_THROW(prep::horizontalLattice(grid, 2.5), data::Error);
    EXPECT_THROW(prep::horizontalLattice(grid, -0.1), data::Error);
    EXPECT_THROW(prep::verticalLattice(grid, {{0.0, 0.0}, {4.5, 1.0}}), data::Error);
    EXPECT_THROW(prep::verticalLattice(grid, {{1.0, 1.0}}), data::Error);
}

TEST(FieldSection, AroundTheGlobeTheSeamsCellJoinsTheLastColumnToTheFirst) {
    const data::Grid grid = smallGrid();
    const std::vector<float> values = linearField(grid);
    // Half way from the last column (x = 4) to the first (x = 0), at y = 1, on level 0.
    const prep::SectionLattice round =
        prep::verticalLattice(grid, {{4.5, 1.0}, {4.0, 1.0}}, /*wrapsX=*/true);
    const std::vector<float> section = prep::sampleSection(grid, values, round);
    EXPECT_FLOAT_EQ(section[0], 0.5F * (4.0F + 10.0F) + 0.5F * (0.0F + 10.0F));
    EXPECT_FLOAT_EQ(section[1], 14.0F);
    // Without the wrap the same place is outside.
    EXPECT_THROW(prep::verticalLattice(grid, {{4.5, 1.0}, {4.0, 1.0}}), data::Error);
}

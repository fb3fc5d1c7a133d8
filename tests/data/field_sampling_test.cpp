// Trilinear sampling between grid points: exact for a linear field, missing corners left out.
#include "data/field_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace ensil;

namespace {
data::Grid smallGrid() {
    return data::Grid(data::makeUniformAxis("x", "", 0, 3, 4),
                      data::makeUniformAxis("y", "", 0, 2, 3),
                      data::makeUniformAxis("z", "", 0, 1, 2));
}
}  // namespace

TEST(FieldSampling, IsExactForALinearFieldAndLeavesOutMissingCorners) {
    const data::Grid grid = smallGrid();
    std::vector<float> values(grid.pointCount());
    for (std::size_t k = 0; k < 2; ++k)
        for (std::size_t j = 0; j < 3; ++j)
            for (std::size_t i = 0; i < 4; ++i)
                values[grid.index(i, j, k)] = float(1 + 2 * i + 10 * j + 100 * k);
    EXPECT_FLOAT_EQ(data::sampleTrilinear(grid, values, {1.5, 0.5, 0.25}), 1 + 3 + 5 + 25);
    EXPECT_FLOAT_EQ(data::sampleTrilinear(grid, values, {3, 2, 1}), 1 + 6 + 20 + 100);
    // A missing corner: the others decide.
    values[grid.index(0, 0, 0)] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FLOAT_EQ(data::sampleTrilinear(grid, values, {0.5, 0, 0}), 3.0F);
    EXPECT_TRUE(std::isnan(data::sampleTrilinear(grid, values, {0, 0, 0})));
    EXPECT_TRUE(std::isnan(data::sampleTrilinear(grid, std::vector<float>(3, 1.0F), {0, 0, 0})))
        << "not one value per point";
}

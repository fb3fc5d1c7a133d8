// The floor's column maxima (engine/floor_map.h): the mean's, and the members' spread,
// worked out by hand on a 2 x 2 x 2 grid.
#include "engine/floor_map.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ensil;

namespace {
// t in K on a 2 x 2 x 2 grid, members to be added.
data::Ensemble temperaturesOnACube() {
    data::Ensemble e;
    e.variable = "t";
    e.units = "K";
    e.grid = data::Grid(data::makeUniformAxis("x", "m", 0, 1, 2),
                        data::makeUniformAxis("y", "m", 0, 1, 2),
                        data::makeUniformAxis("z", "m", 0, 1, 2));
    return e;
}
}  // namespace

TEST(FloorMap, TheSpreadFloorIsTheColumnMaximumOfTheSampleStandardDeviation) {
    // Three members on x = 0, 1 and two levels (the two rows alike). Column x = 0: level 0 holds 1,
    // 2, 3 (sample sd 1), level 1 holds 0, 0, 6 (mean 2, sd sqrt((4 + 4 + 16) / 2) = sqrt(12));
    // column x = 1: level 0 holds 5, 5, 5 (sd 0), level 1 holds 1, NaN, 3 (sd sqrt(2)).
    data::Ensemble e = temperaturesOnACube();
    const float nan = std::nanf("");
    // Per member, its value at (x, z); both rows y = 0 and y = 1 alike.
    const float value[3][2][2] = {{{1, 0}, {5, 1}}, {{2, 0}, {5, nan}}, {{3, 6}, {5, 3}}};
    const auto field = [&](const auto& at) {
        data::FieldValues values(e.grid.pointCount());
        for (std::size_t k = 0; k < 2; ++k) {
            for (std::size_t j = 0; j < 2; ++j) {
                for (std::size_t i = 0; i < 2; ++i) values[e.grid.index(i, j, k)] = at(i, k);
            }
        }
        return values;
    };
    for (std::size_t m = 0; m < 3; ++m) {
        e.members.push_back(
            {"m", field([&](std::size_t i, std::size_t k) { return value[m][i][k]; })});
    }
    const float meanValue[2][2] = {{2, 2}, {5, 2}};
    const data::Member mean{"mean",
                            field([&](std::size_t i, std::size_t k) { return meanValue[i][k]; })};
    const engine::ColumnMaxima maxima = engine::computeColumnMaxima(e, mean);
    ASSERT_EQ(maxima.spread.size(), 4u);  // nx * ny
    for (const std::size_t row : {0U, 2U}) {
        EXPECT_NEAR(maxima.spread[row], std::sqrt(12.0), 1e-5);
        EXPECT_NEAR(maxima.spread[row + 1], std::sqrt(2.0), 1e-5);
    }
    EXPECT_EQ(maxima.mean, (std::vector<float>{2, 5, 2, 5}));

    gl::RenderSettings settings;
    settings.floor = gl::FloorContent::SpreadMaximum;
    const gl::FloorMap floor = engine::floorMapFor(e, mean, maxima, settings);
    EXPECT_EQ(floor.values, maxima.spread);
    EXPECT_TRUE(floor.caption.contains("standard deviation of t [K]"))
        << floor.caption.toStdString();
}

TEST(FloorMap, TheProbabilityFloorKeepsTheScaleOfAProbabilityAndSaysItsIsovalue) {
    data::Ensemble e = temperaturesOnACube();
    engine::ColumnMaxima maxima;
    gl::RenderSettings settings;
    settings.floor = gl::FloorContent::ProbabilityMaximum;
    const data::Member mean{"mean", data::FieldValues(8, 1.0F)};
    EXPECT_TRUE(engine::floorMapFor(e, mean, maxima, settings).values.empty())
        << "no isovalue yet: no floor";
    maxima.exceedance = {0.2F, 0.4F, 0.4F, 0.6F};
    maxima.isovalue = 273.15F;
    const gl::FloorMap floor = engine::floorMapFor(e, mean, maxima, settings);
    EXPECT_EQ(floor.values, maxima.exceedance);
    // 0 to 1, not the values' own 0.2 to 0.6: a probability of 0.6 must not look certain.
    EXPECT_EQ(floor.minimum, 0.0F);
    EXPECT_EQ(floor.maximum, 1.0F);
    EXPECT_EQ(floor.caption, QStringLiteral("floor: column maximum of P(t > 273.1 K)"));
}

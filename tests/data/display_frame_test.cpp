#include "data/display_frame.h"

#include <gtest/gtest.h>

#include <cmath>

#include "data/demo_ensemble.h"

using namespace ensil;

namespace {
data::Grid demoGrid() {
    return data::makeDemoEnsemble({.members = 1, .nx = 25, .ny = 11, .nz = 6}).ensemble.grid;
}
}  // namespace

TEST(DisplayFrame, HorizontalProportionsAreKeptAndAtmosphereIsAThinSlab) {
    const data::DisplayFrame frame(demoGrid(), 1.0F);
    EXPECT_FLOAT_EQ(frame.boxMax().x, 1.0F);            // 120 degrees of longitude
    EXPECT_FLOAT_EQ(frame.boxMax().y, 50.0F / 120.0F);  // 50 degrees of latitude
    EXPECT_FLOAT_EQ(frame.boxMax().z, 0.2F);
    EXPECT_TRUE(frame.logPressure());
    const data::DisplayFrame exaggerated(demoGrid(), 3.0F);
    EXPECT_FLOAT_EQ(exaggerated.boxMax().z, 0.6F);
}

TEST(DisplayFrame, PressureMapsThroughLogPressureWithLowPressureOnTop) {
    const data::DisplayFrame frame(demoGrid(), 1.0F);
    const float top = frame.boxMax().z;
    EXPECT_NEAR(frame.toDisplay({0, 50, 1000}).z, 0.0F, 1e-6);
    EXPECT_NEAR(frame.toDisplay({0, 50, 100}).z, top, 1e-6);
    // sqrt(1000 * 100) hPa is halfway up in log-pressure.
    EXPECT_NEAR(frame.toDisplay({0, 50, std::sqrt(1000.0 * 100.0)}).z, 0.5F * top, 1e-5);
    EXPECT_NEAR(frame.toDisplay({-80, 25, 500}).x, 0.0F, 1e-6);
    EXPECT_NEAR(frame.toDisplay({40, 75, 500}).y, frame.boxMax().y, 1e-6);
}

TEST(DisplayFrame, IndexSpaceCornersAreBoxCorners) {
    const data::Grid grid = demoGrid();
    const data::DisplayFrame frame(grid, 1.0F);
    const glm::vec3 first = frame.indexToDisplay({0, 0, 0});
    const glm::vec3 last = frame.indexToDisplay({24, 10, 5});
    EXPECT_NEAR(first.x, 0.0F, 1e-6);
    EXPECT_NEAR(first.y, 0.0F, 1e-6);
    EXPECT_NEAR(first.z, 0.0F, 1e-6);
    EXPECT_NEAR(last.x, frame.boxMax().x, 1e-6);
    EXPECT_NEAR(last.y, frame.boxMax().y, 1e-6);
    EXPECT_NEAR(last.z, frame.boxMax().z, 1e-6);
    // Half an index step in x is half a cell of longitude: 2.5 degrees of 120.
    EXPECT_NEAR(frame.indexToDisplay({0.5F, 0, 0}).x, 2.5F / 120.0F, 1e-6);
}

TEST(DisplayFrame, VolumeInOneUnitKeepsTrueProportions) {
    const data::Grid cube(data::makeUniformAxis("x", "", 0, 67, 68),
                          data::makeUniformAxis("y", "", 0, 67, 68),
                          data::makeUniformAxis("z", "", 0, 33.5, 35));
    const data::DisplayFrame frame(cube, 1.0F);
    EXPECT_FALSE(frame.logPressure());
    EXPECT_FLOAT_EQ(frame.boxMax().z, 0.5F);
    EXPECT_TRUE(data::isPressureUnit("hPa"));
    EXPECT_TRUE(data::isPressureUnit("Pa"));
    EXPECT_FALSE(data::isPressureUnit("m"));
}

TEST(DisplayFrame, DisplayToIndexUndoesIndexToDisplayOnLogPressure) {
    const data::Grid grid(
        data::makeUniformAxis("lon", "degrees_east", 0, 357, 120),
        data::makeUniformAxis("lat", "degrees_north", 90, -90, 61),
        data::Axis{"plev", "Pa", "air_pressure", {100000, 85000, 50000, 20000}, false});
    const data::DisplayFrame frame(grid, 2.0F);
    for (const glm::vec3 index : {glm::vec3{0, 0, 0}, glm::vec3{17.25F, 40.5F, 1.5F},
                                  glm::vec3{119, 60, 3}, glm::vec3{3, 59.9F, 2.75F}}) {
        const glm::dvec3 back = frame.displayToIndex(frame.indexToDisplay(index));
        EXPECT_NEAR(back.x, index.x, 1e-3);
        EXPECT_NEAR(back.y, index.y, 1e-3);
        EXPECT_NEAR(back.z, index.z, 1e-3);
    }
    // Outside the box clamps to the grid.
    EXPECT_DOUBLE_EQ(frame.displayToIndex({-1.0F, 0.0F, 0.0F}).x, 0.0);
}

// The vertical axis as chosen (issue 40): 500 hPa in a box from 1000 to 100 hPa lies at
// log(1000/500)/log(10) of its height through log-pressure, at 500/900 linearly in pressure, and
// at the standard atmosphere's heights (ICAO table: 1000 hPa 111 m, 500 hPa 5574 m, 100 hPa
// 16,180 m) at (5574 - 111) / (16180 - 111). Each maps back to its level.
TEST(DisplayFrame, APressureAxisIsDrawnThroughLogPressureLinearlyOrAtStandardHeights) {
    data::Axis p;
    p.name = "plev";
    p.units = "Pa";
    p.positiveUp = false;
    p.values = {100000, 85000, 70000, 50000, 25000, 10000};
    const data::Grid grid(data::makeUniformAxis("lon", "degrees_east", 0, 90, 10),
                          data::makeUniformAxis("lat", "degrees_north", 0, 45, 6), p);
    const auto fraction = [&](data::VerticalAxis axis) {
        const data::DisplayFrame frame(grid, 1.0F, axis);
        return frame.toDisplay({0.0, 0.0, 50000.0}).z / frame.boxMax().z;
    };
    EXPECT_NEAR(fraction(data::VerticalAxis::LogPressure), std::log(2.0) / std::log(10.0), 1e-6);
    EXPECT_NEAR(fraction(data::VerticalAxis::Pressure), 500.0 / 900.0, 1e-6);
    EXPECT_NEAR(fraction(data::VerticalAxis::StandardHeight), (5574.0 - 111.0) / (16180.0 - 111.0),
                2e-4);
    for (const auto axis : {data::VerticalAxis::LogPressure, data::VerticalAxis::Pressure,
                            data::VerticalAxis::StandardHeight}) {
        const data::DisplayFrame frame(grid, 2.0F, axis);
        EXPECT_EQ(frame.verticalAxis(), axis);
        for (double k = 0.0; k <= 5.0; k += 0.5) {
            const glm::vec3 shown = frame.indexToDisplay({1.0F, 1.0F, static_cast<float>(k)});
            EXPECT_NEAR(frame.displayToIndex(shown).z, k, 1e-4) << static_cast<int>(axis);
        }
    }
    // Another vertical axis is drawn as it is, whatever the choice.
    const data::Grid heights(grid.x(), grid.y(), data::makeUniformAxis("z", "m", 0, 5000, 6));
    const data::DisplayFrame linear(heights, 1.0F, data::VerticalAxis::StandardHeight);
    EXPECT_FALSE(linear.pressureAxis());
    EXPECT_NEAR(linear.toDisplay({0.0, 0.0, 1000.0}).z / linear.boxMax().z, 0.2, 1e-6);
}

// The vertical scale a figure states (data/vertical_scale.h): the standard atmosphere's heights
// against its published table, and the stretch of boxes whose true proportions are worked out
// here by hand.
#include "data/vertical_scale.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ensil;

TEST(VerticalScale, StandardAtmosphereHeightsMatchTheTable) {
    // ICAO / ISO 2533 geopotential heights of the mandatory levels, metres.
    EXPECT_NEAR(data::standardAtmosphereHeight(1013.25), 0.0, 0.5);
    EXPECT_NEAR(data::standardAtmosphereHeight(850.0), 1457.0, 2.0);
    EXPECT_NEAR(data::standardAtmosphereHeight(500.0), 5574.0, 2.0);
    EXPECT_NEAR(data::standardAtmosphereHeight(226.32), 11000.0, 2.0);
    EXPECT_NEAR(data::standardAtmosphereHeight(100.0), 16180.0, 3.0);
    EXPECT_NEAR(data::standardAtmosphereHeight(10.0), 31055.0, 5.0);
}

TEST(VerticalScale, AnAtmosphereOverAGlobeIsStretchedByThousands) {
    // 360 degrees of longitude span the display's 1; 850 to 500 hPa are drawn 0.2 high.
    const data::Grid grid(data::makeUniformAxis("lon", "degrees_east", 0, 360, 9),
                          data::makeUniformAxis("lat", "degrees_north", -90, 90, 5),
                          data::makeUniformAxis("plev", "hPa", 850, 500, 2));
    const data::DisplayFrame frame(grid, 1.0F);
    const auto scale = data::verticalScaleOf(grid, frame);
    ASSERT_TRUE(scale.has_value());
    EXPECT_TRUE(scale->standardAtmosphere);
    const double metresPerDegree = 6371008.8 * M_PI / 180.0;
    const double expected = 0.2 * 360.0 * metresPerDegree / (5574.0 - 1457.0);
    EXPECT_NEAR(scale->factor, expected, expected * 1e-3);
    // The exaggeration the user chose multiplies it; Pa are hPa a hundredth.
    const data::Grid inPascals(grid.x(), grid.y(),
                               data::makeUniformAxis("plev", "Pa", 85000, 50000, 2));
    EXPECT_NEAR(data::verticalScaleOf(inPascals, data::DisplayFrame(inPascals, 3.0F))->factor,
                3.0 * expected, 3.0 * expected * 1e-3);
}

TEST(VerticalScale, ABoxInMetresOnItsOwnUnitsIsTrueAndModelLevelsSayNothing) {
    // x, y and z all in metres: drawn in true proportion (display_frame.h), a factor of 1.
    const data::Grid metres(data::makeUniformAxis("x", "m", 0, 2000, 3),
                            data::makeUniformAxis("y", "m", 0, 1000, 3),
                            data::makeUniformAxis("z", "m", 0, 500, 3));
    const auto scale = data::verticalScaleOf(metres, data::DisplayFrame(metres, 1.0F));
    ASSERT_TRUE(scale.has_value());
    EXPECT_NEAR(scale->factor, 1.0, 1e-6);
    EXPECT_FALSE(scale->standardAtmosphere);
    // Heights in km over a map in degrees.
    const data::Grid km(data::makeUniformAxis("lon", "degrees_east", 0, 10, 3),
                        data::makeUniformAxis("lat", "degrees_north", 0, 5, 3),
                        data::makeUniformAxis("height", "km", 0, 10, 3));
    const double kmFactor = 0.2 * 10.0 * 6371008.8 * M_PI / 180.0 / 10000.0;
    EXPECT_NEAR(data::verticalScaleOf(km, data::DisplayFrame(km, 1.0F))->factor, kmFactor,
                kmFactor * 1e-6);
    // Model level numbers have no true height.
    const data::Grid levels(km.x(), km.y(), data::makeUniformAxis("model_level", "1", 1, 30, 30));
    EXPECT_FALSE(data::verticalScaleOf(levels, data::DisplayFrame(levels, 1.0F)).has_value());
}

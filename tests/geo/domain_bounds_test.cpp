// lonLatBounds: the true longitudes and latitudes a grid covers, checked on the real rotated
// uk_hires grid against every grid point taken back to geographic coordinates without PROJ.
#include "geo/domain_bounds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "data/ensemble_reader.h"
#include "tests/geo/rotated_pole.h"
#include "tests/support/shared_data.h"

using namespace ensil;

namespace {
using test::sharedDataFile;
}  // namespace

TEST(DomainBounds, UkHiresRotatedGridLiesOverIrelandAndNorthernEnglandAsItsPointsSay) {
    const data::EnsembleDescription d = data::describeEnsemble(
        {.paths = {sharedDataFile("uk_hires.nc")}, .memberDimension = "time"});
    ASSERT_EQ(d.gridMapping.name, "rotated_latitude_longitude");
    ASSERT_EQ(d.gridMapping.parameter("grid_north_pole_latitude"), 37.5);
    ASSERT_EQ(d.gridMapping.parameter("grid_north_pole_longitude"), 177.5);
    const geo::MapProjection projection = geo::MapProjection::forGrid(d.grid, d.gridMapping);
    const auto bounds = geo::lonLatBounds(d.grid, projection);
    ASSERT_TRUE(bounds.has_value());

    // Independently: every grid point, through the rotation written out.
    const test::RotatedPole pole(177.5, 37.5);
    double lonMin = std::numeric_limits<double>::infinity();
    double lonMax = -lonMin;
    double latMin = lonMin;
    double latMax = -lonMin;
    for (const double x : d.grid.x().values) {
        for (const double y : d.grid.y().values) {
            const glm::dvec2 p = pole.toGeographic({x, y});
            lonMin = std::min(lonMin, p.x);
            lonMax = std::max(lonMax, p.x);
            latMin = std::min(latMin, p.y);
            latMax = std::max(latMax, p.y);
        }
    }
    EXPECT_NEAR(bounds->lonMin, lonMin, 0.05);
    EXPECT_NEAR(bounds->lonMax, lonMax, 0.05);
    EXPECT_NEAR(bounds->latMin, latMin, 0.05);
    EXPECT_NEAR(bounds->latMax, latMax, 0.05);
    // Ireland to northern England.
    EXPECT_LT(bounds->lonMin, -6.0);
    EXPECT_GT(bounds->lonMax, -3.0);
    EXPECT_GT(bounds->latMin, 49.0);
    EXPECT_LT(bounds->latMax, 57.0);
}

TEST(DomainBounds, ALongitudeLatitudeGridIsItsOwnAxes) {
    const data::EnsembleDescription d =
        data::describeEnsemble({.paths = {sharedDataFile("era5_eda_members.nc")}, .variable = "t"});
    EXPECT_TRUE(d.gridMapping.empty());
    const geo::MapProjection projection = geo::MapProjection::forGrid(d.grid, d.gridMapping);
    const auto bounds = geo::lonLatBounds(d.grid, projection);
    ASSERT_TRUE(bounds.has_value());
    EXPECT_DOUBLE_EQ(bounds->lonMin, d.grid.x().minValue());
    EXPECT_DOUBLE_EQ(bounds->lonMax, d.grid.x().maxValue());
    EXPECT_DOUBLE_EQ(bounds->latMin, -90.0);
    EXPECT_DOUBLE_EQ(bounds->latMax, 90.0);
}

TEST(DomainBounds, AProjectedGridAroundThePoleCoversEveryLongitude) {
    const data::Grid grid(data::makeUniformAxis("x", "km", -2000.0, 2000.0, 20),
                          data::makeUniformAxis("y", "km", -2000.0, 2000.0, 20),
                          data::makeUniformAxis("z", "m", 0.0, 1.0e4, 3));
    const data::GridMapping arctic{"polar_stereographic",
                                   {{"latitude_of_projection_origin", {90.0}},
                                    {"straight_vertical_longitude_from_pole", {-45.0}},
                                    {"standard_parallel", {70.0}}}};
    const auto bounds = geo::lonLatBounds(grid, geo::MapProjection::forGrid(grid, arctic));
    ASSERT_TRUE(bounds.has_value());
    EXPECT_EQ(bounds->latMax, 90.0);
    EXPECT_EQ(bounds->lonMax - bounds->lonMin, 360.0);
    // The square's corners, 2828 km from the pole, lie near 64.3 N.
    EXPECT_GT(bounds->latMin, 63.0);
    EXPECT_LT(bounds->latMin, 66.0);
}

TEST(DomainBounds, ADomainAcrossTheAntimeridianEndsPast180) {
    // A rotated grid centred on 180 E at the equator: pole at 90 N, origin moved to 180.
    const data::Grid grid(data::makeUniformAxis("rlon", "degrees", -10.0, 10.0, 20),
                          data::makeUniformAxis("rlat", "degrees", -5.0, 5.0, 20),
                          data::makeUniformAxis("z", "m", 0.0, 1.0e4, 3));
    const data::GridMapping mapping{
        "rotated_latitude_longitude",
        {{"grid_north_pole_latitude", {90.0}}, {"grid_north_pole_longitude", {0.0}}}};
    const auto bounds = geo::lonLatBounds(grid, geo::MapProjection::forGrid(grid, mapping));
    ASSERT_TRUE(bounds.has_value());
    EXPECT_NEAR(bounds->lonMin, 170.0, 1e-6);
    EXPECT_NEAR(bounds->lonMax, 190.0, 1e-6);
}

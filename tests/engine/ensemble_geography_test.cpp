// Where a file's grid lies on the Earth, from its CF grid mapping (engine::geographyOf, as
// `ensil info` and the workbench's coastlines use it): a Met Office UK grid on the Lambert
// azimuthal equal-area projection, written as IMPROVER writes one.
#include <gtest/gtest.h>

#include <string>

#include "data/ensemble_reader.h"
#include "engine/ensemble_info.h"
#include "tests/data/netcdf_test_file.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

TEST(EnsembleGeography, ALambertAzimuthalEqualAreaGridLiesOverTheBritishIsles) {
    const test::TempDir dir;
    const std::string path = dir.file("improver_uk.nc");
    {
        test::NcTestFile f(path);
        const int realization =
            f.dim("realization", 3, {0, 1, 2}, {{"standard_name", "realization"}});
        const int height = f.dim("height", 3, {10, 500, 1500},
                                 {{"units", "m"}, {"positive", "up"}, {"axis", "Z"}});
        // 200 km cells from 600 km south-west to 600 km north-east of the projection's origin.
        const int y = f.dim("projection_y_coordinate", 7, test::range(7, -600000.0, 200000.0),
                            {{"units", "m"}, {"standard_name", "projection_y_coordinate"}});
        const int x = f.dim("projection_x_coordinate", 7, test::range(7, -600000.0, 200000.0),
                            {{"units", "m"}, {"standard_name", "projection_x_coordinate"}});
        const int crs = f.variable("lambert_azimuthal_equal_area", NC_INT, {});
        f.text(crs, "grid_mapping_name", "lambert_azimuthal_equal_area");
        f.number(crs, "latitude_of_projection_origin", NC_DOUBLE, {54.9});
        f.number(crs, "longitude_of_projection_origin", NC_DOUBLE, {-2.5});
        f.number(crs, "false_easting", NC_DOUBLE, {0.0});
        f.number(crs, "false_northing", NC_DOUBLE, {0.0});
        f.number(crs, "semi_major_axis", NC_DOUBLE, {6378137.0});
        f.number(crs, "semi_minor_axis", NC_DOUBLE, {6356752.314140356});
        const int t = f.variable("air_temperature", NC_FLOAT, {realization, height, y, x});
        f.text(t, "units", "K");
        f.text(t, "grid_mapping", "lambert_azimuthal_equal_area");
        f.write(t, std::size_t{3} * 3 * 7 * 7,
                [](std::size_t i) { return 280.0 + static_cast<double>(i % 17); });
    }
    data::DataSelection selection;
    selection.paths = {path};
    const data::EnsembleDescription d = data::describeEnsemble(selection);
    EXPECT_EQ(d.gridMapping.name, "lambert_azimuthal_equal_area");
    const engine::Geography geography = engine::geographyOf(d);
    ASSERT_TRUE(geography.bounds.has_value()) << geography.why;
    // 600 km each way from 54.9 N 2.5 W: 5.4 degrees of latitude (111.2 km a degree), and at
    // the corners, 600 km east or west at about 50 and 60 N, 8 to 11 degrees of longitude.
    EXPECT_NEAR(geography.bounds->latMin, 54.9 - 5.4, 0.5);
    EXPECT_NEAR(geography.bounds->latMax, 54.9 + 5.4, 0.5);
    EXPECT_LT(geography.bounds->lonMin, -2.5 - 9.0);
    EXPECT_GT(geography.bounds->lonMin, -2.5 - 15.0);
    EXPECT_GT(geography.bounds->lonMax, -2.5 + 9.0);
    EXPECT_LT(geography.bounds->lonMax, -2.5 + 15.0);
}

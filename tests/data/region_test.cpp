// The region a selection keeps (data/region.h): parsing, choosing the columns and rows (across
// the 0/360 seam and the date line, latitudes either way, edges included), and reading only
// them through every path a reader is called by (NetCDF whole and in parts, as hyperslabs; GRIB
// read whole and cut), against the whole read's values picked by their indices.
#include "data/region.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "data/ensemble_part.h"
#include "data/ensemble_reader.h"
#include "data/error.h"
#include "data/netcdf_writer.h"
#include "tests/data/reader_test_helpers.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {

std::string regionErrorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const data::Error& e) {
        return e.what();
    }
    return "no error";
}

// A global ensemble on a 10-degree grid, longitudes 0..350, whose every value names its member,
// layer, row and column (m * 10^6 + k * 10^4 + j * 100 + i, exact in float).
data::Ensemble indexedGlobe(bool northToSouth) {
    data::Ensemble e;
    e.variable = "t";
    e.units = "K";
    e.memberDimension = "number";
    data::Axis lon = data::makeUniformAxis("lon", "degrees_east", 0.0, 350.0, 36);
    lon.standardName = "longitude";
    data::Axis lat = northToSouth ? data::makeUniformAxis("lat", "degrees_north", 90.0, -90.0, 19)
                                  : data::makeUniformAxis("lat", "degrees_north", -90.0, 90.0, 19);
    lat.standardName = "latitude";
    data::Axis plev;
    plev.name = "plev";
    plev.units = "hPa";
    plev.values = {1000, 850, 500};
    plev.positiveUp = false;
    e.grid = data::Grid(lon, lat, plev);
    for (std::size_t m = 0; m < 2; ++m) {
        data::Member member{"member " + std::to_string(m + 1), {}};
        member.values.resize(e.grid.pointCount());
        for (std::size_t k = 0; k < 3; ++k) {
            for (std::size_t j = 0; j < 19; ++j) {
                for (std::size_t i = 0; i < 36; ++i) {
                    member.values[e.grid.index(i, j, k)] =
                        static_cast<float>(m * 1000000 + k * 10000 + j * 100 + i);
                }
            }
        }
        e.members.push_back(std::move(member));
    }
    return e;
}

// The values of `whole` at the columns `is` and rows `js` (in that order) of layers
// [firstLayer, firstLayer + layers) of members [firstMember, firstMember + members).
std::vector<float> picked(const data::Ensemble& whole, const std::vector<std::size_t>& is,
                          const std::vector<std::size_t>& js, std::size_t firstLayer = 0,
                          std::size_t layers = 0, std::size_t firstMember = 0,
                          std::size_t members = 0) {
    if (layers == 0) layers = whole.grid.nz();
    if (members == 0) members = whole.members.size();
    std::vector<float> values;
    for (std::size_t m = firstMember; m < firstMember + members; ++m) {
        for (std::size_t k = firstLayer; k < firstLayer + layers; ++k) {
            for (const std::size_t j : js) {
                for (const std::size_t i : is) {
                    values.push_back(whole.members[m].values[whole.grid.index(i, j, k)]);
                }
            }
        }
    }
    return values;
}

std::vector<float> allValuesOf(const data::Ensemble& e) {
    std::vector<float> all;
    for (const data::Member& m : e.members) all.insert(all.end(), m.values.begin(), m.values.end());
    return all;
}

// The indices whose coordinates lie in [lo, hi], in the axis's order.
std::vector<std::size_t> indicesWithin(const data::Axis& axis, double lo, double hi) {
    std::vector<std::size_t> is;
    for (std::size_t i = 0; i < axis.size(); ++i) {
        if (axis.values[i] >= lo && axis.values[i] <= hi) is.push_back(i);
    }
    return is;
}

// Coordinates made by adding and subtracting 360 (or stored as float) match within 1e-9.
void expectCoordinates(const std::vector<double>& actual, const std::vector<double>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        EXPECT_NEAR(actual[i], expected[i], 1e-9) << "coordinate " << i;
    }
}

std::vector<std::size_t> concat(std::vector<std::size_t> a, const std::vector<std::size_t>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

}  // namespace

TEST(Region, ParsesFourNumbersAndSaysWhatIsWrong) {
    EXPECT_EQ(data::parseRegion("-10,40,35,72"), (data::Region{-10, 40, 35, 72}));
    EXPECT_EQ(data::parseRegion(" 350 , 20, 35 ,70 "), (data::Region{350, 20, 35, 70}));
    EXPECT_EQ(data::parseRegion("0.25,1e1,-90,90"), (data::Region{0.25, 10, -90, 90}));
    EXPECT_EQ(data::parseRegion("-180,180,72,35"), (data::Region{-180, 180, 72, 35}));
    // What regionText writes (projects keep it) reads back the same.
    for (const char* text : {"-10,40,35,72", "350,20,35,70", "0.125,359.875,-89.5,89.5"}) {
        const data::Region region = data::parseRegion(text);
        EXPECT_EQ(data::parseRegion(data::regionText(region)), region) << text;
    }
    EXPECT_EQ(data::regionText({-10, 40, 35.5, 72}), "-10,40,35.5,72");

    const std::vector<std::pair<const char*, const char*>> bad{
        {"-10,40,35", "has 3 values"},
        {"-10,40,35,72,5", "has 5 values"},
        {"-10:40,35,72", "'-10:40' for LON0, which is not a number"},
        {"-10,,35,72", "has no LON1"},
        {"-10,40,35,north", "'north' for LAT1"},
        {"-10,40,95,72", "LAT0 = 95, not a latitude from -90 to 90"},
        {"-10,400,35,72", "LON1 = 400, not a longitude from -360 to 360"},
        {"10,10,35,72", "has no width"},
        {"-10,40,35,35", "has no height"},
        {"-180,200,35,72", "spans 380 degrees of longitude"},
        {"nan,40,35,72", "'nan' for LON0"},
        {"", "has no LON0"}};
    for (const auto& entry : bad) {
        const std::string text = entry.first;
        const std::string why = entry.second;
        const std::string message = regionErrorOf([&] { (void)data::parseRegion(text); });
        EXPECT_NE(message.find(std::string("the region '") + text + "' "), std::string::npos)
            << message;
        EXPECT_NE(message.find(why), std::string::npos) << message;
        EXPECT_NE(message.find("LON0,LON1,LAT0,LAT1 in degrees"), std::string::npos) << message;
    }
    EXPECT_NE(regionErrorOf([] {
                  data::checkRegion({0, 10, -91, 0});
              }).find("the region '0,10,-91,0' has LAT0 = -91"),
              std::string::npos);
}

// On a 0..350 grid, -10..40 is the columns 350, 0, 10, ..., 40, written as -10..40; 350..20
// the columns 350 to 20 written as -10..20 (never past 360); edges included; rows in the file's
// order.
TEST(Region, ColumnsWrapAcrossTheSeamInTheOrderTheLongitudesRun) {
    const data::Grid grid = indexedGlobe(true).grid;
    data::HorizontalWindow w = data::regionWithin(grid, {}, {-10, 40, 35, 72}, "globe");
    EXPECT_EQ(w.columns, (std::vector<data::ColumnRun>{{35, 1, -360.0}, {0, 5, 0.0}}));
    EXPECT_EQ(w.firstRow, 2U);  // 70 N, down to 40 N
    EXPECT_EQ(w.rowCount, 4U);
    data::Grid kept = data::gridWindow(grid, w);
    expectCoordinates(kept.x().values, {-10, 0, 10, 20, 30, 40});
    EXPECT_EQ(kept.y().values, (std::vector<double>{70, 60, 50, 40}));
    EXPECT_EQ(kept.z().values, grid.z().values);

    // 350..20 is the same box: written a turn lower rather than as 350..380.
    w = data::regionWithin(grid, {}, {350, 20, 35, 72}, "globe");
    EXPECT_EQ(w.columns, (std::vector<data::ColumnRun>{{35, 1, -360.0}, {0, 3, 0.0}}));
    expectCoordinates(data::gridWindow(grid, w).x().values, {-10, 0, 10, 20});
    // So is 360..20: the file's 0 .. 20.
    w = data::regionWithin(grid, {}, {360, 20, 35, 72}, "globe");
    EXPECT_EQ(w.columns, (std::vector<data::ColumnRun>{{0, 3, 0.0}}));

    // A box within the grid's longitudes: one run, the file's own longitudes.
    w = data::regionWithin(grid, {}, {20, 50, -20, 20}, "globe");
    EXPECT_EQ(w.columns, (std::vector<data::ColumnRun>{{2, 4, 0.0}}));
    EXPECT_EQ(w.firstRow, 7U);
    EXPECT_EQ(w.rowCount, 5U);
    // Typed in the other convention: the same columns, written as typed.
    w = data::regionWithin(grid, {}, {-170, -140, -20, 20}, "globe");
    EXPECT_EQ(w.columns, (std::vector<data::ColumnRun>{{19, 4, -360.0}}));
    expectCoordinates(data::gridWindow(grid, w).x().values, {-170, -160, -150, -140});

    // The whole globe from -180: all 36 columns, 180..350 first, each meridian once.
    w = data::regionWithin(grid, {}, {-180, 180, -90, 90}, "globe");
    EXPECT_EQ(w.columns, (std::vector<data::ColumnRun>{{18, 18, -360.0}, {0, 18, 0.0}}));
    EXPECT_EQ(w.rowCount, 19U);

    // Edges within 1e-4 degrees count (coordinates stored as float); 1e-3 beyond do not.
    w = data::regionWithin(grid, {}, {-9.99995, 39.99995, 40.00005, 69.99995}, "globe");
    EXPECT_EQ(w.columnCount(), 6U);
    EXPECT_EQ(w.rowCount, 4U);
    w = data::regionWithin(grid, {}, {-9.999, 39.999, 40.001, 69.999}, "globe");
    EXPECT_EQ(w.columnCount(), 4U);
    EXPECT_EQ(w.rowCount, 2U);
}

// A file whose latitudes run south to north keeps its rows in that order too.
TEST(Region, LatitudesEitherWayRoundKeepTheFilesOrder) {
    const data::Grid grid = indexedGlobe(false).grid;
    const data::HorizontalWindow w = data::regionWithin(grid, {}, {-10, 40, 72, 35}, "globe");
    EXPECT_EQ(w.firstRow, 13U);  // 40 N, up to 70 N
    EXPECT_EQ(w.rowCount, 4U);
    EXPECT_EQ(data::gridWindow(grid, w).y().values, (std::vector<double>{40, 50, 60, 70}));
}

// NetCDF reads only the columns and rows kept (two hyperslabs across the seam), whole and in
// parts, with the values of the whole read at those indices, on files with latitudes either
// way round; the levels kept combine with them.
TEST(Region, NetcdfReadsOnlyTheRegionKeptWholeAndInParts) {
    for (const bool northToSouth : {true, false}) {
        SCOPED_TRACE(northToSouth ? "north to south" : "south to north");
        const test::TempDir dir;
        const std::string path = dir.file("globe.nc");
        data::writeNetcdf(indexedGlobe(northToSouth), path);
        const data::DataSelection all = test::selection({path});
        const data::Ensemble whole = data::openEnsemble(all);
        ASSERT_EQ(whole.grid.nx(), 36U);

        data::DataSelection europe = all;
        europe.region = data::Region{-10, 40, 35, 72};
        const std::vector<std::size_t> is{35, 0, 1, 2, 3, 4};
        const std::vector<std::size_t> js = indicesWithin(whole.grid.y(), 35, 72);
        ASSERT_EQ(js.size(), 4U);

        const data::EnsembleDescription described = data::describeEnsemble(europe);
        ASSERT_TRUE(described.keptRegion);
        EXPECT_EQ(described.keptRegion->fileX.values, whole.grid.x().values);
        EXPECT_EQ(described.grid.nx(), 6U);
        EXPECT_EQ(described.grid.ny(), 4U);
        EXPECT_EQ(described.bytes(), std::size_t{2} * 6 * 4 * 3 * sizeof(float));
        const data::Ensemble kept = data::openEnsemble(europe);
        expectCoordinates(kept.grid.x().values, {-10, 0, 10, 20, 30, 40});
        EXPECT_EQ(kept.grid.y().values, described.grid.y().values);
        EXPECT_EQ(kept.grid.x().units, "degrees_east");
        EXPECT_EQ(allValuesOf(kept), picked(whole, is, js));

        // A slab of the region kept, as the streaming passes read it.
        const data::Ensemble slab = data::openEnsemblePart(
            europe, described,
            {.firstMember = 1, .memberCount = 1, .firstLayer = 1, .layerCount = 2});
        EXPECT_EQ(slab.grid.x().values, kept.grid.x().values);
        EXPECT_EQ(allValuesOf(slab), picked(whole, is, js, 1, 2, 1, 1));

        // With the levels kept as well: the layers 850 and 500 hPa of the same columns.
        data::DataSelection both = europe;
        both.levels = data::LevelRange{850, 500, "hPa"};
        EXPECT_EQ(allValuesOf(data::openEnsemble(both)), picked(whole, is, js, 1, 2));
        const data::EnsembleDescription bothDescribed = data::describeEnsemble(both);
        EXPECT_EQ(data::fileDescription(bothDescribed).grid.pointCount(), whole.grid.pointCount());
        EXPECT_EQ(allValuesOf(data::openEnsemblePart(
                      both, bothDescribed,
                      {.firstMember = 0, .memberCount = 2, .firstLayer = 0, .layerCount = 2})),
                  picked(whole, is, js, 1, 2));

        // East of the seam, in one hyperslab.
        data::DataSelection east = all;
        east.region = data::Region{20, 50, 72, 35};
        EXPECT_EQ(allValuesOf(data::openEnsemble(east)), picked(whole, {2, 3, 4, 5}, js));

        EXPECT_NE(data::sourceIdentity(europe), data::sourceIdentity(all));
        EXPECT_NE(data::sourceIdentity(europe), data::sourceIdentity(east));
    }
}

// GRIB is read whole and cut afterwards: the same ensemble as its NetCDF twin read as
// hyperslabs, across the seam of its 0..357 grid, and across the date line of a -180..179.25
// grid (ERA-Interim's).
TEST(Region, AFormatReadWholeIsCutToTheSameRegion) {
    const data::Region region{-30, 45, 30, 75};
    data::DataSelection grib =
        test::selection({test::sharedDataFile("era5-levels-members.grib")}, "t");
    data::DataSelection netcdf =
        test::selection({test::sharedDataFile("era5_eda_members.nc")}, "t");
    const data::Ensemble wholeGrib = data::openEnsemble(grib);
    grib.region = region;
    netcdf.region = region;
    const data::Ensemble keptGrib = data::openEnsemble(grib);
    const data::Ensemble keptNetcdf = data::openEnsemble(netcdf);
    const std::vector<std::size_t> is = concat(indicesWithin(wholeGrib.grid.x(), 330, 360),
                                               indicesWithin(wholeGrib.grid.x(), 0, 45));
    const std::vector<std::size_t> js = indicesWithin(wholeGrib.grid.y(), 30, 75);
    ASSERT_EQ(is.size(), 26U);  // 330..357 and 0..45 every 3 degrees
    EXPECT_EQ(keptGrib.grid.nx(), is.size());
    EXPECT_DOUBLE_EQ(keptGrib.grid.x().front(), -30.0);
    EXPECT_DOUBLE_EQ(keptGrib.grid.x().back(), 45.0);
    EXPECT_EQ(keptGrib.grid.y().values, keptNetcdf.grid.y().values);
    expectCoordinates(keptGrib.grid.x().values, keptNetcdf.grid.x().values);
    EXPECT_EQ(allValuesOf(keptGrib), picked(wholeGrib, is, js));
    EXPECT_EQ(allValuesOf(keptGrib), allValuesOf(keptNetcdf));

    data::DataSelection eraInterim = test::selection({test::sharedDataFile("eraint_uvz.nc")}, "u");
    eraInterim.memberDimension = "month";
    const data::Ensemble wholeEraInterim = data::openEnsemble(eraInterim);
    eraInterim.region = data::Region{170, -170, -10, 10};
    const data::Ensemble pacific = data::openEnsemble(eraInterim);
    const std::vector<std::size_t> across =
        concat(indicesWithin(wholeEraInterim.grid.x(), 170, 180),
               indicesWithin(wholeEraInterim.grid.x(), -180, -170));
    EXPECT_EQ(pacific.grid.nx(), across.size());
    // Its columns lie every 0.75 degrees from -180: 170.25 ... 179.25, then -179.25 ... -170.25
    // written as 180.75 ... 189.75.
    EXPECT_DOUBLE_EQ(pacific.grid.x().front(), 170.25);
    EXPECT_DOUBLE_EQ(pacific.grid.x().back(), 189.75);
    EXPECT_EQ(allValuesOf(pacific),
              picked(wholeEraInterim, across, indicesWithin(wholeEraInterim.grid.y(), -10, 10)));
}

// A grid that is not a regular longitude-latitude one is refused naming the file and why; a box
// with no grid point (or a single column) names the grid's extent and is a RegionOutsideGrid.
TEST(Region, RefusesGridsThatAreNotLongitudeLatitudeAndBoxesWithoutPoints) {
    data::DataSelection rotated =
        test::selection({test::sharedDataFile("uk_hires.nc")}, "air_potential_temperature");
    rotated.memberDimension = "time";
    rotated.region = data::Region{-5, 0, 50, 55};
    std::string message = regionErrorOf([&] { (void)data::describeEnsemble(rotated); });
    EXPECT_NE(message.find("cannot keep the region -5,0,50,55 of 'air_potential_temperature' in "),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("uk_hires.nc"), std::string::npos) << message;
    EXPECT_NE(message.find("lies on a 'rotated_latitude_longitude' grid"), std::string::npos)
        << message;
    EXPECT_NE(message.find("regular longitude-latitude grid"), std::string::npos) << message;

    data::DataSelection volume = test::selection({test::sharedDataFile("ironProt.vtk")});
    volume.region = data::Region{0, 10, 0, 10};
    message = regionErrorOf([&] { (void)data::openEnsemble(volume); });
    EXPECT_NE(message.find("its horizontal axes ('x', 'y') are not longitude and latitude"),
              std::string::npos)
        << message;

    const test::TempDir dir;
    const std::string path = dir.file("globe.nc");
    data::writeNetcdf(indexedGlobe(true), path);
    data::DataSelection nothing = test::selection({path});
    nothing.region = data::Region{1, 9, 35, 72};  // between two columns
    try {
        (void)data::openEnsemble(nothing);
        ADD_FAILURE() << "a box between the columns opened";
    } catch (const data::RegionOutsideGrid& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "the region 1,9,35,72 holds no grid point of 't' in " + path +
                      ", whose grid spans longitudes 0 to 350 and latitudes 90 to -90 (36 x 19 "
                      "points)"),
                  std::string::npos)
            << e.what();
    }
    data::DataSelection one = nothing;
    one.region = data::Region{5, 15, 35, 72};
    message = regionErrorOf([&] { (void)data::describeEnsemble(one); });
    EXPECT_NE(message.find("holds only 1 column and 4 rows (a volume needs 2 of each)"),
              std::string::npos)
        << message;
}

#include "data/statistics_writer.h"

#include <gtest/gtest.h>
#include <netcdf.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "data/cf_conventions.h"
#include "data/error.h"
#include "data/netcdf_file.h"
#include "tests/support/temp_dir.h"

using namespace ensil::data;

namespace {
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

std::string textAttribute(int nc, int var, const char* name) {
    std::size_t length = 0;
    if (nc_inq_attlen(nc, var, name, &length) != NC_NOERR) return "<missing>";
    std::string value(length, '\0');
    nc_get_att_text(nc, var, name, value.data());
    return value;
}

// 3 x 2 x 2 points, latitude falling and pressure levels as a file has them; 2 x 1 x 1 cells.
Grid smallGrid() {
    Axis lon = makeUniformAxis("lon", "degrees_east", 0.0, 20.0, 3);
    lon.standardName = "longitude";
    Axis lat = makeUniformAxis("lat", "degrees_north", 50.0, 40.0, 2);
    lat.standardName = "latitude";
    Axis plev{"plev", "hPa", "air_pressure", {850.0, 500.0}, false};
    return Grid(std::move(lon), std::move(lat), std::move(plev));
}

// Every field distinct from every other, so a field written in another's place shows.
struct Values {
    std::vector<float> count, mean, stddev, minimum, maximum, range, exceedance, crossing;
};
Values valuesFor(std::size_t points, std::size_t cells) {
    Values v;
    for (std::size_t p = 0; p < points; ++p) {
        const auto f = static_cast<float>(p);
        v.count.push_back(p == 5 ? 0.0F : 3.0F);
        v.mean.push_back(p == 5 ? kNaN : 250.0F + f);
        v.stddev.push_back(p == 5 ? kNaN : 1.0F + 0.5F * f);
        v.minimum.push_back(p == 5 ? kNaN : 240.0F + f);
        v.maximum.push_back(p == 5 ? kNaN : 270.0F + f);
        v.range.push_back(p == 5 ? kNaN : 30.0F);
        v.exceedance.push_back(p == 5 ? kNaN : (f / 12.0F));
    }
    for (std::size_t c = 0; c < cells; ++c) v.crossing.push_back(c == 0 ? 0.25F : kNaN);
    return v;
}

StatisticsFile fileOf(const Grid& grid, const Values& v) {
    StatisticsFile f;
    f.variable = "t";
    f.longName = "Temperature";
    f.units = "K";
    f.grid = grid;
    f.fixedDimensions = {"time = 0 of 4 (2017-01-01T00:00)"};
    f.isovalue = 260.0F;
    f.members = {"member 0", "member 2", "member 5"};
    f.sources = {"/data/era5.nc"};
    f.history = "2025-01-01T00:00:00Z: ensil stats /data/era5.nc --iso 260 --out s.nc";
    f.count = v.count;
    f.mean = v.mean;
    f.stddev = v.stddev;
    f.minimum = v.minimum;
    f.maximum = v.maximum;
    f.range = v.range;
    f.exceedance = v.exceedance;
    f.levelCrossing = v.crossing;
    return f;
}

std::vector<float> readFloats(int nc, const char* name, std::size_t n) {
    int var = -1;
    EXPECT_EQ(nc_inq_varid(nc, name, &var), NC_NOERR) << name;
    std::vector<float> values(n);
    EXPECT_EQ(nc_get_var_float(nc, var, values.data()), NC_NOERR) << name;
    return values;
}

void expectSameValues(const std::vector<float>& actual, const std::vector<float>& expected,
                      const char* name) {
    ASSERT_EQ(actual.size(), expected.size()) << name;
    for (std::size_t i = 0; i < actual.size(); ++i) {
        if (std::isnan(expected[i])) {
            EXPECT_TRUE(std::isnan(actual[i])) << name << " at " << i;
        } else {
            EXPECT_EQ(actual[i], expected[i]) << name << " at " << i;
        }
    }
}
}  // namespace

TEST(StatisticsWriter, WritesEveryFieldWithItsCfAttributes) {
    ensil::test::TempDir dir;
    const Grid grid = smallGrid();
    const Values v = valuesFor(grid.pointCount(), 2);
    const std::string path = dir.file("stats.nc");
    writeStatisticsNetcdf(fileOf(grid, v), path);

    int nc = -1;
    ASSERT_EQ(nc_open(path.c_str(), NC_NOWRITE, &nc), NC_NOERR);
    struct Expected {
        const char* name;
        const std::vector<float>* values;
        const char* units;
        const char* longName;
        const char* cellMethods;
    };
    const std::array<Expected, 7> onPoints{{
        {"mean", &v.mean, "K", "ensemble mean of t", "realization: mean"},
        {"stddev", &v.stddev, "K", "ensemble standard deviation of t (sample, n - 1)",
         "realization: standard_deviation"},
        {"min", &v.minimum, "K", "ensemble minimum of t", "realization: minimum"},
        {"max", &v.maximum, "K", "ensemble maximum of t", "realization: maximum"},
        {"range", &v.range, "K", "ensemble range of t (max - min)", "realization: range"},
        {"exceedance_probability", &v.exceedance, "1", "probability that t exceeds 260 K",
         "<missing>"},
        {"member_count", &v.count, "1", "number of members with a finite value of t", "<missing>"},
    }};
    for (const Expected& e : onPoints) {
        int var = -1;
        ASSERT_EQ(nc_inq_varid(nc, e.name, &var), NC_NOERR) << e.name;
        nc_type type = 0;
        int ndims = 0;
        std::array<int, NC_MAX_VAR_DIMS> dims{};
        nc_inq_var(nc, var, nullptr, &type, &ndims, dims.data(), nullptr);
        EXPECT_EQ(type, NC_FLOAT) << e.name;
        ASSERT_EQ(ndims, 3) << e.name;
        const std::array<std::string, 3> names{"plev", "lat", "lon"};
        const std::array<std::size_t, 3> sizes{2, 2, 3};
        for (int d = 0; d < 3; ++d) {
            std::array<char, NC_MAX_NAME + 1> name{};
            std::size_t size = 0;
            nc_inq_dim(nc, dims[d], name.data(), &size);
            EXPECT_EQ(std::string(name.data()), names[d]) << e.name;
            EXPECT_EQ(size, sizes[d]) << e.name;
        }
        EXPECT_EQ(textAttribute(nc, var, "units"), e.units) << e.name;
        EXPECT_EQ(textAttribute(nc, var, "long_name"), e.longName) << e.name;
        EXPECT_EQ(textAttribute(nc, var, "cell_methods"), e.cellMethods) << e.name;
        EXPECT_EQ(textAttribute(nc, var, "grid_mapping"), "<missing>") << e.name;
        float fill = 0.0F;
        ASSERT_EQ(nc_get_att_float(nc, var, "_FillValue", &fill), NC_NOERR) << e.name;
        EXPECT_TRUE(std::isnan(fill)) << e.name;
        expectSameValues(readFloats(nc, e.name, grid.pointCount()), *e.values, e.name);
    }

    // The cell grid: its own dimensions, coordinates at the cell centres.
    int crossing = -1;
    ASSERT_EQ(nc_inq_varid(nc, "level_crossing_probability", &crossing), NC_NOERR);
    int ndims = 0;
    std::array<int, NC_MAX_VAR_DIMS> dims{};
    nc_inq_var(nc, crossing, nullptr, nullptr, &ndims, dims.data(), nullptr);
    ASSERT_EQ(ndims, 3);
    const std::array<std::string, 3> cellNames{"plev_cell", "lat_cell", "lon_cell"};
    const std::array<std::vector<double>, 3> centres{
        std::vector<double>{675.0}, std::vector<double>{45.0}, std::vector<double>{5.0, 15.0}};
    for (int d = 0; d < 3; ++d) {
        std::array<char, NC_MAX_NAME + 1> name{};
        std::size_t size = 0;
        nc_inq_dim(nc, dims[d], name.data(), &size);
        EXPECT_EQ(std::string(name.data()), cellNames[d]);
        ASSERT_EQ(size, centres[d].size()) << cellNames[d];
        int coord = -1;
        ASSERT_EQ(nc_inq_varid(nc, name.data(), &coord), NC_NOERR) << name.data();
        std::vector<double> values(size);
        nc_get_var_double(nc, coord, values.data());
        EXPECT_EQ(values, centres[d]) << name.data();
    }
    int lonCell = -1;
    nc_inq_varid(nc, "lon_cell", &lonCell);
    EXPECT_EQ(textAttribute(nc, lonCell, "units"), "degrees_east");
    EXPECT_EQ(textAttribute(nc, lonCell, "standard_name"), "longitude");
    EXPECT_EQ(textAttribute(nc, lonCell, "long_name"), "longitude at cell centres");
    EXPECT_EQ(textAttribute(nc, lonCell, "axis"), "X");
    int plevCell = -1;
    nc_inq_varid(nc, "plev_cell", &plevCell);
    EXPECT_EQ(textAttribute(nc, plevCell, "positive"), "down");
    EXPECT_EQ(textAttribute(nc, crossing, "units"), "1");
    EXPECT_EQ(textAttribute(nc, crossing, "long_name"),
              "probability that the t = 260 K isosurface crosses the cell");
    expectSameValues(readFloats(nc, "level_crossing_probability", 2), v.crossing,
                     "level_crossing_probability");

    // The point coordinates, as the grid has them (latitude falling).
    int lat = -1;
    ASSERT_EQ(nc_inq_varid(nc, "lat", &lat), NC_NOERR);
    std::vector<double> latValues(2);
    nc_get_var_double(nc, lat, latValues.data());
    EXPECT_EQ(latValues, (std::vector<double>{50.0, 40.0}));
    EXPECT_EQ(textAttribute(nc, lat, "units"), "degrees_north");
    EXPECT_EQ(textAttribute(nc, lat, "axis"), "Y");

    EXPECT_EQ(textAttribute(nc, NC_GLOBAL, "Conventions"), "CF-1.8");
    EXPECT_EQ(textAttribute(nc, NC_GLOBAL, "title"),
              "ensemble statistics of t (Temperature) at isovalue 260 K, time = 0 of 4 "
              "(2017-01-01T00:00)");
    EXPECT_EQ(textAttribute(nc, NC_GLOBAL, "source"), "/data/era5.nc");
    EXPECT_EQ(textAttribute(nc, NC_GLOBAL, "history"),
              "2025-01-01T00:00:00Z: ensil stats /data/era5.nc --iso 260 --out s.nc");
    EXPECT_EQ(textAttribute(nc, NC_GLOBAL, "members"), "member 0, member 2, member 5");
    nc_type isovalueType = 0;
    ASSERT_EQ(nc_inq_atttype(nc, NC_GLOBAL, "isovalue", &isovalueType), NC_NOERR);
    EXPECT_EQ(isovalueType, NC_FLOAT);  // the float the statistics used, as it was
    float isovalue = 0.0F;
    ASSERT_EQ(nc_get_att_float(nc, NC_GLOBAL, "isovalue", &isovalue), NC_NOERR);
    EXPECT_EQ(isovalue, 260.0F);
    nc_close(nc);
}

TEST(StatisticsWriter, CarriesTheGridMappingThatEnsilReadsBackAndTheMembersAxis) {
    ensil::test::TempDir dir;
    Axis rlon = makeUniformAxis("rlon", "degrees", -5.0, 5.0, 4);
    rlon.standardName = "grid_longitude";
    Axis rlat = makeUniformAxis("rlat", "degrees", -3.0, 3.0, 3);
    rlat.standardName = "grid_latitude";
    const Grid grid(std::move(rlon), std::move(rlat), makeUniformAxis("z", "m", 0.0, 100.0, 2));
    const Values v = valuesFor(grid.pointCount(), 6);
    StatisticsFile f = fileOf(grid, v);
    f.gridMapping.name = "rotated_latitude_longitude";
    f.gridMapping.parameters = {{"grid_north_pole_latitude", {39.25}},
                                {"grid_north_pole_longitude", {-162.0}},
                                {"_FillValue", {-1.0}}};
    f.memberAxis = "time";  // members along time, as --member-dim time makes them
    const std::string path = dir.file("rotated.nc");
    writeStatisticsNetcdf(f, path);

    NetcdfFile file(path);
    for (const char* name : {"mean", "stddev", "min", "max", "range", "exceedance_probability",
                             "member_count", "level_crossing_probability"}) {
        const NcVariable* var = file.findVariable(name);
        ASSERT_NE(var, nullptr) << name;
        EXPECT_EQ(file.text(var->id, "grid_mapping"), "crs") << name;
        const GridMapping read = readGridMapping(file, *var);
        EXPECT_EQ(read.name, "rotated_latitude_longitude") << name;
        EXPECT_EQ(read.parameter("grid_north_pole_latitude"), 39.25) << name;
        EXPECT_EQ(read.parameter("grid_north_pole_longitude"), -162.0) << name;
        EXPECT_FALSE(read.parameter("_FillValue").has_value()) << name;
    }
    EXPECT_EQ(file.text(file.findVariable("mean")->id, "cell_methods"), "time: mean");
    EXPECT_EQ(file.text(file.findVariable("range")->id, "cell_methods"), "time: range");
    EXPECT_EQ(file.text(file.findVariable("member_count")->id, "cell_methods"), "");
}

TEST(StatisticsWriter, RefusesAFieldOfTheWrongSizeAndLeavesNoFile) {
    ensil::test::TempDir dir;
    const Grid grid = smallGrid();
    Values v = valuesFor(grid.pointCount(), 2);
    v.stddev.pop_back();
    const std::string path = dir.file("bad.nc");
    try {
        writeStatisticsNetcdf(fileOf(grid, v), path);
        FAIL() << "a short stddev was written";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidArgument);
        EXPECT_NE(std::string(e.what()).find("stddev has 11 values, the grid 12"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
    v = valuesFor(grid.pointCount(), 3);  // one cell too many
    EXPECT_THROW(writeStatisticsNetcdf(fileOf(grid, v), path), Error);
    EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(StatisticsWriter, UnwritablePathIsATypedErrorNamingTheFile) {
    const Grid grid = smallGrid();
    const Values v = valuesFor(grid.pointCount(), 2);
    const std::string path = "/nonexistent-folder-for-ensil/stats.nc";
    try {
        writeStatisticsNetcdf(fileOf(grid, v), path);
        FAIL() << "writing into a missing folder succeeded";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::WriteFailed);
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(StatisticsWriter, CellCentresAreTheMeansOfNeighbours) {
    const Axis plev{"plev", "Pa", "air_pressure", {100000.0, 85000.0, 50000.0}, false};
    EXPECT_EQ(cellCentres(plev), (std::vector<double>{92500.0, 67500.0}));
    EXPECT_EQ(cellDimensionName(plev), "plev_cell");
}

TEST(StatisticsWriter, AFailedWriteRemovesThePartialFile) {
    // An axis named like one of the statistics: the file is created, then the variable's name
    // is taken. The error names the file and the variable; nothing is left behind.
    ensil::test::TempDir dir;
    const Grid grid(makeUniformAxis("range", "m", 0.0, 2.0, 3), makeUniformAxis("y", "m", 0, 1, 2),
                    makeUniformAxis("z", "m", 0.0, 1.0, 2));
    const Values v = valuesFor(grid.pointCount(), 2);
    const std::string path = dir.file("partial.nc");
    try {
        writeStatisticsNetcdf(fileOf(grid, v), path);
        FAIL() << "a file with two variables named 'range' was written";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::WriteFailed);
        EXPECT_NE(std::string(e.what()).find("define variable range in '" + path + "'"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
}

// The real files in tests/data/real, written by others: each opens, or is refused with the
// right message.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <array>
#include <cmath>

#include "data/ensemble_reader.h"
#include "data/error.h"
#include "tests/data/reader_test_helpers.h"
#include "tests/support/shared_data.h"

using namespace ensil;

namespace {
using test::sharedDataFile;

float rawValue(const std::string& path, const char* var, std::vector<std::size_t> index) {
    int nc = -1, id = -1;
    float value = 0;
    EXPECT_EQ(nc_open(path.c_str(), NC_NOWRITE, &nc), NC_NOERR);
    EXPECT_EQ(nc_inq_varid(nc, var, &id), NC_NOERR);
    EXPECT_EQ(nc_get_var1_float(nc, id, index.data(), &value), NC_NOERR);
    nc_close(nc);
    return value;
}

}  // namespace

TEST(RealFiles, Era5EdaIsATenMemberEnsembleAlongNumber) {
    const std::string path = sharedDataFile("era5_eda_members.nc");
    const auto d = data::describeEnsemble({.paths = {path}, .variable = "t", .timeIndex = 1});
    EXPECT_EQ(d.memberDimension, "number");
    EXPECT_EQ(d.memberDimensionReason,
              "coordinate variable 'number' has standard_name = realization");
    EXPECT_EQ(d.members, 10u);
    EXPECT_EQ(d.units, "K");
    EXPECT_EQ(d.grid.nx(), 120u);
    EXPECT_EQ(d.grid.ny(), 61u);
    EXPECT_EQ(d.grid.nz(), 2u);
    EXPECT_EQ(d.grid.z().units, "Pa");
    EXPECT_FALSE(d.grid.z().positiveUp);
    const data::Ensemble e = data::openEnsemble({.paths = {path}, .variable = "t", .timeIndex = 1});
    // (number=3, time=1, plev=1, lat=10, lon=20) as stored.
    EXPECT_EQ(e.members[3].values[e.grid.index(20, 10, 1)], rawValue(path, "t", {3, 1, 1, 10, 20}));
}

TEST(RealFiles, Era5InNetcdfAndGribHasTheSameFourDatedSteps) {
    const data::TimeSteps expected{
        .dimension = "time",
        .labels = {"2017-01-01T00:00", "2017-01-01T12:00", "2017-01-02T00:00", "2017-01-02T12:00"}};
    for (const char* name : {"era5_eda_members.nc", "era5-levels-members.grib"}) {
        const auto d = data::describeEnsemble({.paths = {sharedDataFile(name)}, .timeIndex = 2});
        EXPECT_EQ(d.timeSteps, expected) << name;
        EXPECT_EQ(data::openEnsemble({.paths = {sharedDataFile(name)}, .variable = "t"}).timeSteps,
                  expected)
            << name << ": the ensemble read keeps them";
    }
    // Times made the members: the members' index is what is left to step through.
    const auto byTime = data::describeEnsemble(
        {.paths = {sharedDataFile("era5-levels-members.grib")}, .memberDimension = "time"});
    EXPECT_EQ(byTime.timeSteps.dimension, "number");
    EXPECT_EQ(byTime.timeSteps.count(), 10u);
    EXPECT_EQ(byTime.timeSteps.labels.front(), "0");
}

TEST(RealFiles, EraInterimPackedShortsAndDerivedWindSpeed) {
    const std::string path = sharedDataFile("eraint_uvz.nc");
    EXPECT_EQ(test::errorOpening({.paths = {path}}).kind(),
              data::ErrorKind::MemberDimensionNotFound);
    const data::DataSelection u{.paths = {path}, .variable = "u", .memberDimension = "month"};
    const data::Ensemble eu = data::openEnsemble(u);
    ASSERT_EQ(eu.memberCount(), 2u);
    // Unpacking: raw short * scale_factor + add_offset, scale_factor negative in this file.
    const float raw = rawValue(path, "u", {1, 2, 100, 200});
    const float expected = static_cast<float>(raw * -0.00157270493804553 + 26.96875);
    EXPECT_NEAR(eu.members[1].values[eu.grid.index(200, 100, 2)], expected, 1e-4);

    data::DataSelection v = u, speed = u;
    v.variable = "v";
    speed.variable = "wind_speed";
    const data::Ensemble ev = data::openEnsemble(v);
    const data::Ensemble es = data::openEnsemble(speed);
    EXPECT_EQ(es.units, "m s**-1");
    float maximum = 0;
    for (std::size_t p = 0; p < es.grid.pointCount(); p += 97) {
        const float a = eu.members[0].values[p], b = ev.members[0].values[p];
        ASSERT_NEAR(es.members[0].values[p], std::sqrt(a * a + b * b), 1e-4);
        maximum = std::max(maximum, es.members[0].values[p]);
    }
    EXPECT_GT(maximum, 30.0F) << "January jet streams exceed 30 m/s at 200 hPa";
}

TEST(RealFiles, GloSea4HasNoVerticalAxisAndSaysSo) {
    const data::Error e =
        test::errorOpening({.paths = {sharedDataFile("glosea4_surface_temperature_ensemble.nc")}});
    EXPECT_EQ(e.kind(), data::ErrorKind::NotThreeDimensional);
    const std::string m = e.what();
    EXPECT_NE(m.find("surface_temperature"), std::string::npos) << m;
    EXPECT_NE(m.find("no vertical"), std::string::npos) << m;
}

TEST(RealFiles, UkHiresTimeStandsInForMembersOnHybridHeights) {
    const data::Ensemble e =
        data::openEnsemble({.paths = {sharedDataFile("uk_hires.nc")}, .memberDimension = "time"});
    ASSERT_EQ(e.memberCount(), 3u);
    EXPECT_EQ(e.members[0].name, "2009-11-19T10:00");
    EXPECT_EQ(e.grid.nx(), 187u);
    EXPECT_EQ(e.grid.ny(), 204u);
    EXPECT_EQ(e.grid.z().name, "level_height");
    EXPECT_EQ(e.grid.z().units, "m");
    EXPECT_FALSE(e.grid.z().isUniform());
    EXPECT_TRUE(e.grid.x().isUniform()) << "float-stored rotated longitudes are evenly spaced";
}

TEST(RealFiles, ContourForecastTimesWithFillValuesAndValidRange) {
    const std::string path = sharedDataFile("contour.cdf");
    const data::Error e = test::errorOpening({.paths = {path}});
    EXPECT_EQ(e.kind(), data::ErrorKind::MemberDimensionNotFound);
    EXPECT_NE(std::string(e.what()).find("--member-dim frtime"), std::string::npos) << e.what();

    const data::Ensemble z =
        data::openEnsemble({.paths = {path}, .variable = "Z", .memberDimension = "frtime"});
    ASSERT_EQ(z.memberCount(), 7u);
    EXPECT_EQ(z.timeSteps, data::TimeSteps{}) << "the forecast times are the members: no steps";
    const data::Grid& g = z.grid;
    // valid_range [-150, 5000] m masks the upper levels (100 hPa is ~16 km up); 1000 hPa stays.
    std::size_t bottomValid = 0, topValid = 0;
    for (std::size_t j = 0; j < g.ny(); ++j)
        for (std::size_t i = 0; i < g.nx(); ++i) {
            bottomValid += std::isnan(z.members[0].values[g.index(i, j, 0)]) ? 0 : 1;
            topValid += std::isnan(z.members[0].values[g.index(i, j, g.nz() - 1)]) ? 0 : 1;
        }
    EXPECT_EQ(g.z().values.back(), 100.0);
    EXPECT_EQ(topValid, 0u);
    EXPECT_GT(bottomValid, g.nx() * g.ny() / 2);
}

TEST(RealFiles, GribAndVtkAreNotMistakenForNetcdf) {
    // The GRIB file goes to the GRIB reader (tests/data/grib_reader_test.cpp compares it with
    // its NetCDF conversion).
    EXPECT_EQ(
        data::describeEnsemble({.paths = {sharedDataFile("era5-levels-members.grib")}}).format,
        "GRIB 1");

    // The VTK volume goes to the VTK reader; two copies make a two-member ensemble.
    const data::Ensemble iron = data::openEnsemble({.paths = {sharedDataFile("ironProt.vtk")}});
    EXPECT_EQ(iron.memberCount(), 1u);
    EXPECT_EQ(iron.grid.pointCount(), 68u * 68u * 68u);
    EXPECT_EQ(data::describeEnsemble({.paths = {sharedDataFile("ironProt.vtk")}}).format,
              "VTK legacy");
}

#include "data/netcdf_writer.h"

#include <gtest/gtest.h>
#include <netcdf.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "data/error.h"
#include "tests/support/temp_dir.h"

using namespace ensil::data;

namespace {
std::string textAttribute(int nc, int var, const char* name) {
    std::size_t length = 0;
    if (nc_inq_attlen(nc, var, name, &length) != NC_NOERR) return "<missing>";
    std::string value(length, '\0');
    nc_get_att_text(nc, var, name, value.data());
    return value;
}
}  // namespace

TEST(NetcdfWriter, WritesCfFileThatReadsBackExactly) {
    ensil::test::TempDir dir;
    Ensemble e = makeDemoEnsemble({.members = 4, .nx = 12, .ny = 6, .nz = 5, .seed = 2}).ensemble;
    e.members[1].values[17] = std::numeric_limits<float>::quiet_NaN();
    const std::string path = dir.file("demo.nc");
    writeNetcdf(e, path);

    int nc = -1;
    ASSERT_EQ(nc_open(path.c_str(), NC_NOWRITE, &nc), NC_NOERR);
    int var = -1;
    ASSERT_EQ(nc_inq_varid(nc, "wind_speed", &var), NC_NOERR);
    int ndims = 0;
    std::array<int, NC_MAX_VAR_DIMS> dims{};
    nc_inq_var(nc, var, nullptr, nullptr, &ndims, dims.data(), nullptr);
    ASSERT_EQ(ndims, 4);
    const std::array<std::string, 4> expectedNames{"number", "plev", "lat", "lon"};
    const std::array<std::size_t, 4> expectedSizes{4, 5, 6, 12};
    for (int d = 0; d < 4; ++d) {
        std::array<char, NC_MAX_NAME + 1> name{};
        std::size_t size = 0;
        nc_inq_dim(nc, dims[d], name.data(), &size);
        EXPECT_EQ(std::string(name.data()), expectedNames[d]);
        EXPECT_EQ(size, expectedSizes[d]);
        int coord = -1;  // CF: every dimension has a coordinate variable with units
        ASSERT_EQ(nc_inq_varid(nc, name.data(), &coord), NC_NOERR) << name.data();
        EXPECT_NE(textAttribute(nc, coord, "units"), "<missing>") << name.data();
        EXPECT_NE(textAttribute(nc, coord, "long_name"), "<missing>") << name.data();
    }
    EXPECT_EQ(textAttribute(nc, var, "units"), "m s-1");
    EXPECT_EQ(textAttribute(nc, var, "standard_name"), "wind_speed");
    EXPECT_NE(textAttribute(nc, var, "long_name"), "<missing>");
    EXPECT_EQ(textAttribute(nc, NC_GLOBAL, "Conventions"), "CF-1.8");
    int plev = -1;
    nc_inq_varid(nc, "plev", &plev);
    EXPECT_EQ(textAttribute(nc, plev, "positive"), "down");
    EXPECT_EQ(textAttribute(nc, plev, "axis"), "Z");

    std::vector<float> values(4 * e.grid.pointCount());
    ASSERT_EQ(nc_get_var_float(nc, var, values.data()), NC_NOERR);
    for (std::size_t m = 0; m < 4; ++m) {
        for (std::size_t p = 0; p < e.grid.pointCount(); ++p) {
            const float expected = e.members[m].values[p];
            const float actual = values[m * e.grid.pointCount() + p];
            if (std::isnan(expected)) {
                ASSERT_TRUE(std::isnan(actual));
            } else {
                ASSERT_EQ(actual, expected) << "member " << m << " point " << p;
            }
        }
    }
    std::vector<double> plevValues(5);
    nc_get_var_double(nc, plev, plevValues.data());
    EXPECT_EQ(plevValues, e.grid.z().values);
    nc_close(nc);
}

TEST(NetcdfWriter, StepsGetACfTimeDimensionTheReaderDates) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("steps.nc");
    const DemoEnsembleParams params{.members = 3, .nx = 8, .ny = 6, .nz = 4, .seed = 3};
    writeNetcdfSteps([&](std::size_t t) { return makeDemoEnsembleAt(params, t, 3).ensemble; },
                     {.units = "hours since 2026-01-01 00:00:00", .values = {0, 12, 24}}, path);
    const EnsembleDescription d = describeEnsemble({.paths = {path}});
    EXPECT_EQ(d.memberDimension, "number");
    EXPECT_EQ(d.members, 3u);
    EXPECT_EQ(d.timeSteps,
              (TimeSteps{.dimension = "time",
                         .labels = {"2026-01-01T00:00", "2026-01-01T12:00", "2026-01-02T00:00"}}));
    const Ensemble last = openEnsemble({.paths = {path}, .timeIndex = 2});
    const Ensemble expected = makeDemoEnsembleAt(params, 2, 3).ensemble;
    for (std::size_t m = 0; m < 3; ++m) {
        ASSERT_EQ(std::vector<float>(last.members[m].values.begin(), last.members[m].values.end()),
                  std::vector<float>(expected.members[m].values.begin(),
                                     expected.members[m].values.end()))
            << "member " << m << " of step 2 reads back exactly";
    }
}

TEST(NetcdfWriter, ReportsProgressPerMember) {
    ensil::test::TempDir dir;
    const Ensemble e =
        makeDemoEnsemble({.members = 3, .nx = 4, .ny = 4, .nz = 3, .seed = 1}).ensemble;
    std::vector<std::size_t> seen;
    writeNetcdf(e, dir.file("p.nc"), [&](std::size_t done, std::size_t total) {
        EXPECT_EQ(total, 3u);
        seen.push_back(done);
    });
    EXPECT_EQ(seen, (std::vector<std::size_t>{1, 2, 3}));
}

TEST(NetcdfWriter, UnwritablePathIsATypedErrorNamingTheFile) {
    const Ensemble e =
        makeDemoEnsemble({.members = 2, .nx = 4, .ny = 4, .nz = 3, .seed = 1}).ensemble;
    const std::string path = "/nonexistent-folder-for-ensil/out.nc";
    try {
        writeNetcdf(e, path);
        FAIL() << "writing into a missing folder succeeded";
    } catch (const Error& err) {
        EXPECT_EQ(err.kind(), ErrorKind::WriteFailed);
        EXPECT_NE(std::string(err.what()).find(path), std::string::npos) << err.what();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(NetcdfWriter, RefusesMemberOfWrongSize) {
    ensil::test::TempDir dir;
    Ensemble e = makeDemoEnsemble({.members = 2, .nx = 4, .ny = 4, .nz = 3, .seed = 1}).ensemble;
    e.members[1].values.pop_back();
    EXPECT_THROW(writeNetcdf(e, dir.file("bad.nc")), Error);
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.nc")));
}

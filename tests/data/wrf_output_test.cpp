// WRF output as WRF users read it: its times are named in Times(Time, DateStrLen), a character
// variable, not in a coordinate, and name members along Time and time steps along it; its T is
// the perturbation of the potential temperature from 300 K, from which theta is offered.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "data/ensemble_reader.h"
#include "data/error.h"
#include "data/netcdf_file.h"
#include "tests/data/netcdf_test_file.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {
const std::vector<std::string> kTimes{"2016-10-06_00:00:00", "2016-10-06_03:00:00",
                                      "2016-10-06_06:30:15"};

// A wrfout file: T(Time, bottom_top, south_north, west_east) and Times, with `offset` added to T.
void writeWrfout(const std::string& path, double offset) {
    test::NcTestFile f(path);
    const int time = f.dim("Time", kTimes.size());
    const int length = f.dim("DateStrLen", 19);
    const int z = f.dim("bottom_top", 4);
    const int y = f.dim("south_north", 5);
    const int x = f.dim("west_east", 6);
    const int times = f.variable("Times", NC_CHAR, {time, length});
    const int t = f.variable("T", NC_FLOAT, {time, z, y, x});
    f.text(t, "units", "K");
    f.text(t, "description", "perturbation potential temperature (theta-t0)");
    f.writeRows(times, kTimes, 19);
    f.write(t, kTimes.size() * 4 * 5 * 6,
            [offset](std::size_t i) { return offset + static_cast<double>(i % 120); });
}
}  // namespace

TEST(WrfTimes, MembersAlongTimeAreNamedByTheirDates) {
    const test::TempDir dir;
    const std::string path = dir.file("wrfout_d01_2016-10-06_00:00:00");
    writeWrfout(path, 0.0);
    const data::EnsembleDescription d =
        data::describeEnsemble({.paths = {path}, .memberDimension = "Time"});
    EXPECT_EQ(d.memberNames, (std::vector<std::string>{"2016-10-06T00:00", "2016-10-06T03:00",
                                                       "2016-10-06T06:30:15"}));
    const data::Ensemble e = data::openEnsemble({.paths = {path}, .memberDimension = "Time"});
    ASSERT_EQ(e.memberCount(), 3U);
    EXPECT_EQ(e.members[1].name, "2016-10-06T03:00");
}

TEST(WrfTimes, TimeStepsOfMemberFilesAreLabelledByTheirDates) {
    const test::TempDir dir;
    std::vector<std::string> paths;
    for (int m = 0; m < 2; ++m) {
        paths.push_back(dir.file("wrfout_d01_member" + std::to_string(m)));
        writeWrfout(paths.back(), m);
    }
    const data::EnsembleDescription d = data::describeEnsemble({.paths = paths, .timeIndex = 1});
    EXPECT_EQ(d.timeSteps.labels, (std::vector<std::string>{"2016-10-06T00:00", "2016-10-06T03:00",
                                                            "2016-10-06T06:30:15"}));
}

TEST(WrfTheta, ThePotentialTemperatureIsOfferedAsTPlus300KAndOpensByDefault) {
    const test::TempDir dir;
    const std::string path = dir.file("wrfout_d01");
    writeWrfout(path, 0.0);
    const data::DataSelection time{.paths = {path}, .memberDimension = "Time"};
    const data::EnsembleDescription d = data::describeEnsemble(time);
    const auto theta = std::find_if(d.variables.begin(), d.variables.end(),
                                    [](const auto& v) { return v.name == "theta"; });
    ASSERT_NE(theta, d.variables.end());
    EXPECT_TRUE(theta->derived);
    EXPECT_TRUE(theta->usable);
    EXPECT_EQ(theta->units, "K");
    // T is a perturbation (WRF's `description` says so): theta, not T, is what opens.
    EXPECT_EQ(d.variable, "theta");
    const data::Ensemble t =
        data::openEnsemble({.paths = {path}, .variable = "T", .memberDimension = "Time"});
    const data::Ensemble th = data::openEnsemble(time);
    ASSERT_EQ(th.memberCount(), t.memberCount());
    for (std::size_t i : {std::size_t{0}, std::size_t{37}, t.grid.pointCount() - 1}) {
        EXPECT_FLOAT_EQ(th.members[2].values[i], t.members[2].values[i] + 300.0F) << i;
    }
}

TEST(WindSpeed, DerivedFromGridRelativeXAndYWind) {
    const test::TempDir dir;
    const std::string path = dir.file("ukv.nc");
    {
        test::NcTestFile f(path);
        const int r = f.dim("realization", 2, {0, 1}, {{"standard_name", "realization"}});
        const int z = f.dim("height", 2, {100, 500}, {{"units", "m"}, {"positive", "up"}});
        const int y = f.dim("projection_y_coordinate", 3, {0, 2000, 4000},
                            {{"units", "m"}, {"standard_name", "projection_y_coordinate"}});
        const int x = f.dim("projection_x_coordinate", 4, {0, 2000, 4000, 6000},
                            {{"units", "m"}, {"standard_name", "projection_x_coordinate"}});
        const int u = f.variable("x_wind", NC_FLOAT, {r, z, y, x});
        const int v = f.variable("y_wind", NC_FLOAT, {r, z, y, x});
        f.text(u, "standard_name", "x_wind");
        f.text(v, "standard_name", "y_wind");
        f.text(u, "units", "m s-1");
        f.text(v, "units", "m s-1");
        f.write(u, 48, [](std::size_t) { return 3.0; });
        f.write(v, 48, [](std::size_t) { return 4.0; });
    }
    const data::Ensemble e = data::openEnsemble({.paths = {path}});
    EXPECT_EQ(e.variable, "wind_speed");  // the default: wind speed first
    ASSERT_EQ(e.memberCount(), 2U);
    EXPECT_FLOAT_EQ(e.members[1].values[5], 5.0F);
}

// A header may declare a Times larger than anything a file holds: it is not read (nor allocated),
// and the members keep ensil's numbers.
TEST(WrfTimes, ATimesDeclaredHugeIsLeftUnreadAndTheMembersAreNumbered) {
    const test::TempDir dir;
    const std::string path = dir.file("wrfout_huge_times");
    {
        test::NcTestFile f(path);
        const int time = f.dim("Time", 3);
        const int length = f.dim("DateStrLen", 20'000'000);  // 60 MB of text, never written
        const int z = f.dim("bottom_top", 2);
        const int y = f.dim("south_north", 2);
        const int x = f.dim("west_east", 2);
        (void)f.variable("Times", NC_CHAR, {time, length});
        const int t = f.variable("T", NC_FLOAT, {time, z, y, x});
        f.write(t, 24, [](std::size_t i) { return static_cast<double>(i); });
    }
    const data::NetcdfFile file(path);
    try {
        (void)file.readStrings(*file.findVariable("Times"));
        ADD_FAILURE() << "60 MB of declared text were read";
    } catch (const data::Error& e) {
        EXPECT_EQ(e.kind(), data::ErrorKind::InvalidArgument);
        EXPECT_NE(std::string(e.what()).find("'Times' holds 3 strings of 20000000 characters"),
                  std::string::npos)
            << e.what();
    }
    const data::EnsembleDescription d =
        data::describeEnsemble({.paths = {path}, .memberDimension = "Time"});
    EXPECT_EQ(d.memberNames, (std::vector<std::string>{"member 1", "member 2", "member 3"}));
}

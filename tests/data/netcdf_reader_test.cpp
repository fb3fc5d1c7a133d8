#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "data/ensemble_reader.h"
#include "data/error.h"
#include "netcdf_test_file.h"
#include "tests/support/temp_dir.h"

using namespace ensil;
using data::ErrorKind;
using test::NcTestFile;
using test::range;

namespace {
// f(m, i, j, k) = 1000 m + i + 10 j + 100 k: every value tells where it came from.
double analytic(std::size_t m, std::size_t i, std::size_t j, std::size_t k) {
    return 1000.0 * m + i + 10.0 * j + 100.0 * k;
}

data::ErrorKind errorKindOf(const data::DataSelection& s, std::string* message = nullptr) {
    try {
        (void)data::openEnsemble(s);
    } catch (const data::Error& e) {
        if (message) *message = e.what();
        return e.kind();
    }
    ADD_FAILURE() << "no error";
    return ErrorKind::InvalidArgument;
}

// A (member=3, level=4, lat=5, lon=6) float file with the member dimension named `memberDim`.
std::string writeStandard(const test::TempDir& dir, const std::string& memberDim,
                          std::vector<std::pair<std::string, std::string>> memberAttrs = {}) {
    const std::string path = dir.file(memberDim + ".nc");
    NcTestFile f(path);
    const int m = f.dim(memberDim, 3, range(3), memberAttrs);
    const int z = f.dim("level", 4, {1000, 850, 500, 250}, {{"units", "hPa"}});
    const int y = f.dim("lat", 5, range(5, 30, 5), {{"units", "degrees_north"}});
    const int x = f.dim("lon", 6, range(6, -10, 2), {{"units", "degrees_east"}});
    const int v = f.variable("speed", NC_FLOAT, {m, z, y, x});
    f.text(v, "units", "m s-1");
    f.write(v, 3 * 4 * 5 * 6,
            [](std::size_t n) { return analytic(n / 120, n % 6, (n / 6) % 5, (n / 30) % 4); });
    return path;
}
}  // namespace

TEST(NetcdfReader, ReadsMembersAxesAndValuesInPlace) {
    test::TempDir dir;
    const std::string path = writeStandard(dir, "member");
    const data::Ensemble e = data::openEnsemble({.paths = {path}});
    EXPECT_EQ(e.variable, "speed");
    EXPECT_EQ(e.units, "m s-1");
    EXPECT_EQ(e.memberDimension, "member");
    ASSERT_EQ(e.memberCount(), 3u);
    EXPECT_EQ(e.grid.nx(), 6u);
    EXPECT_EQ(e.grid.ny(), 5u);
    EXPECT_EQ(e.grid.nz(), 4u);
    EXPECT_EQ(e.grid.z().values, (std::vector<double>{1000, 850, 500, 250}));
    EXPECT_FALSE(e.grid.z().positiveUp) << "hPa is a pressure: positive down";
    EXPECT_FALSE(e.grid.z().isUniform());
    for (std::size_t m = 0; m < 3; ++m)
        for (std::size_t k = 0; k < 4; ++k)
            for (std::size_t j = 0; j < 5; ++j)
                for (std::size_t i = 0; i < 6; ++i)
                    ASSERT_EQ(e.members[m].values[e.grid.index(i, j, k)], analytic(m, i, j, k));
}

TEST(NetcdfReader, FindsTheMemberDimensionByEveryRuleInOrder) {
    test::TempDir dir;
    const auto reason = [&](const std::string& dim,
                            std::vector<std::pair<std::string, std::string>> attrs) {
        return data::describeEnsemble({.paths = {writeStandard(dir, dim, std::move(attrs))}});
    };
    EXPECT_EQ(reason("runs", {{"standard_name", "realization"}}).memberDimensionReason,
              "coordinate variable 'runs' has standard_name = realization");
    EXPECT_EQ(reason("eid", {{"standard_name", "ensemble_member_id"}}).memberDimension, "eid");
    EXPECT_EQ(reason("e", {{"_CoordinateAxisType", "Ensemble"}}).memberDimensionReason,
              "coordinate variable 'e' has _CoordinateAxisType = Ensemble");
    for (const char* name :
         {"number", "member", "members", "realization", "ens", "ens0", "ensemble"}) {
        const auto d = reason(name, {});
        EXPECT_EQ(d.memberDimension, name);
        EXPECT_EQ(d.memberDimensionReason, std::string("dimension named '") + name + "'");
    }
}

TEST(NetcdfReader, SpatialDimensionsInAnyOrder) {
    test::TempDir dir;
    const std::string path = dir.file("permuted.nc");
    {
        NcTestFile f(path);
        const int x = f.dim("lon", 4, range(4), {{"units", "degrees_east"}});
        const int m = f.dim("member", 2);
        const int y = f.dim("lat", 3, range(3), {{"units", "degrees_north"}});
        const int z = f.dim("height", 5, range(5, 0, 100), {{"units", "m"}, {"positive", "up"}});
        const int v = f.variable("q", NC_DOUBLE, {x, m, z, y});  // (lon, member, height, lat)
        f.write(v, 4 * 2 * 5 * 3, [](std::size_t n) {
            const std::size_t j = n % 3, k = (n / 3) % 5, member = (n / 15) % 2, i = n / 30;
            return analytic(member, i, j, k);
        });
    }
    const data::Ensemble e = data::openEnsemble({.paths = {path}});
    ASSERT_EQ(e.memberCount(), 2u);
    EXPECT_TRUE(e.grid.z().positiveUp);
    for (std::size_t m = 0; m < 2; ++m)
        for (std::size_t k = 0; k < 5; ++k)
            for (std::size_t j = 0; j < 3; ++j)
                for (std::size_t i = 0; i < 4; ++i)
                    ASSERT_EQ(e.members[m].values[e.grid.index(i, j, k)], analytic(m, i, j, k));
}

TEST(NetcdfReader, UnpacksAndMasksPackedIntegers) {
    test::TempDir dir;
    const std::string path = dir.file("packed.nc");
    {
        NcTestFile f(path);
        const int m = f.dim("number", 2);
        const int z = f.dim("lev", 2);
        const int y = f.dim("y", 2);
        const int x = f.dim("x", 3);
        const int v = f.variable("t", NC_SHORT, {m, z, y, x});
        f.number(v, "scale_factor", NC_DOUBLE, {0.5});
        f.number(v, "add_offset", NC_DOUBLE, {200.0});
        f.number(v, "_FillValue", NC_SHORT, {-32767});
        f.number(v, "missing_value", NC_SHORT, {-999});
        f.number(v, "valid_range", NC_SHORT, {-100, 100});  // packed units, as CF says
        // raw values: n - 10, with a fill, a missing value and an out-of-range one
        f.write(v, 24, [](std::size_t n) {
            return n == 3   ? -32767.0
                   : n == 4 ? -999.0
                   : n == 5 ? 150.0
                            : static_cast<double>(n) - 10.0;
        });
    }
    const data::Ensemble e = data::openEnsemble({.paths = {path}});
    const auto& a = e.members[0].values;
    EXPECT_FLOAT_EQ(a[0], 200.0F - 5.0F);
    EXPECT_FLOAT_EQ(a[2], 200.0F - 4.0F);
    EXPECT_TRUE(std::isnan(a[3]));
    EXPECT_TRUE(std::isnan(a[4]));
    EXPECT_TRUE(std::isnan(a[5]));
    EXPECT_FLOAT_EQ(e.members[1].values[0], 200.0F + 0.5F * (12 - 10));
}

TEST(NetcdfReader, DefaultFillOfUnwrittenFloatsIsMissing) {
    test::TempDir dir;
    const std::string path = dir.file("fill.nc");
    {
        NcTestFile f(path);
        const int m = f.dim("member", 2);
        const int z = f.dim("z", 2);
        const int y = f.dim("y", 2);
        const int x = f.dim("x", 2);
        const int v = f.variable("a", NC_FLOAT, {m, z, y, x});
        f.write(v, 16, [](std::size_t n) { return n == 7 ? NC_FILL_FLOAT : 1.0; });
    }
    const data::Ensemble e = data::openEnsemble({.paths = {path}});
    EXPECT_TRUE(std::isnan(e.members[0].values[7]));
    EXPECT_FLOAT_EQ(e.members[0].values[6], 1.0F);
}

TEST(NetcdfReader, DerivedWindSpeedAndWrfDestaggering) {
    test::TempDir dir;
    const std::string path = dir.file("wrf.nc");
    {
        NcTestFile f(path);
        const int t = f.dim("Time", 1);
        const int z = f.dim("bottom_top", 2);
        const int y = f.dim("south_north", 3);
        const int ys = f.dim("south_north_stag", 4);
        const int x = f.dim("west_east", 4);
        const int xs = f.dim("west_east_stag", 5);
        const int u = f.variable("U", NC_FLOAT, {t, z, y, xs});
        const int v = f.variable("V", NC_FLOAT, {t, z, ys, x});
        f.write(u, 2 * 3 * 5, [](std::size_t n) { return static_cast<double>(n % 5); });  // u = i
        f.write(v, 2 * 4 * 4, [](std::size_t) { return 2.0; });
    }
    const data::EnsembleDescription d = data::describeEnsemble(
        {.paths = {path}, .variable = "wind_speed", .memberDimension = "Time"});
    EXPECT_EQ(d.grid.nx(), 4u);
    EXPECT_EQ(d.grid.ny(), 3u);
    const data::Ensemble e =
        data::openEnsemble({.paths = {path}, .variable = "wind_speed", .memberDimension = "Time"});
    ASSERT_EQ(e.memberCount(), 1u);
    // Destaggered u at mass point i is (i + i + 1) / 2; v is 2 everywhere.
    for (std::size_t i = 0; i < 4; ++i) {
        const float u = static_cast<float>(i) + 0.5F;
        EXPECT_FLOAT_EQ(e.members[0].values[e.grid.index(i, 1, 1)], std::sqrt(u * u + 4.0F));
    }
}

TEST(NetcdfReader, OneFilePerMemberAndGridMismatch) {
    test::TempDir dir;
    const auto write = [&](const std::string& name, std::size_t nx, double value) {
        const std::string path = dir.file(name);
        NcTestFile f(path, NC_CLOBBER);  // classic format
        const int z = f.dim("z", 2, range(2));
        const int y = f.dim("y", 2, range(2));
        const int x = f.dim("x", nx, range(nx));
        const int v = f.variable("vort", NC_FLOAT, {z, y, x});
        f.write(v, 4 * nx, [value](std::size_t) { return value; });
        return path;
    };
    const std::string a = write("run_01.nc", 3, 1.0), b = write("run_02.nc", 3, 2.0);
    const data::Ensemble e = data::openEnsemble({.paths = {a, b}});
    ASSERT_EQ(e.memberCount(), 2u);
    EXPECT_EQ(e.members[0].name, "run_01");
    EXPECT_EQ(e.members[1].name, "run_02");
    EXPECT_FLOAT_EQ(e.members[1].values[5], 2.0F);
    EXPECT_EQ(data::describeEnsemble({.paths = {a, b}}).format, "NetCDF classic");

    const std::string c = write("run_03.nc", 4, 3.0);
    std::string message;
    EXPECT_EQ(errorKindOf({.paths = {a, c}}, &message), ErrorKind::GridMismatch);
    EXPECT_NE(message.find("run_03.nc"), std::string::npos) << message;
    EXPECT_NE(message.find("4 x 2 x 2"), std::string::npos) << message;
}

TEST(NetcdfReader, BadInputGetsTypedErrorsThatSayWhatWouldWork) {
    test::TempDir dir;
    std::string message;
    EXPECT_EQ(errorKindOf({.paths = {dir.file("absent.nc")}}, &message), ErrorKind::FileNotFound);
    EXPECT_NE(message.find("absent.nc"), std::string::npos);

    const std::string text = dir.file("notes.nc");
    std::ofstream(text) << "these are not numbers\n";
    EXPECT_EQ(errorKindOf({.paths = {text}}), ErrorKind::UnsupportedFormat);

    const std::string good = writeStandard(dir, "member");
    EXPECT_EQ(errorKindOf({.paths = {good}, .variable = "temp"}, &message),
              ErrorKind::VariableNotFound);
    EXPECT_NE(message.find("speed"), std::string::npos) << "candidates listed: " << message;

    EXPECT_EQ(errorKindOf({.paths = {dir.path().string()}}, &message), ErrorKind::InvalidArgument);
    EXPECT_NE(message.find("folder"), std::string::npos) << message;

    // Truncated: a valid classic file cut in half.
    const std::string cut = dir.file("cut.nc");
    {
        NcTestFile f(cut, NC_CLOBBER);
        const int z = f.dim("member", 2);
        const int a = f.dim("z", 8), b = f.dim("y", 8), c = f.dim("x", 8);
        const int v = f.variable("f", NC_FLOAT, {z, a, b, c});
        f.write(v, 1024, [](std::size_t n) { return static_cast<double>(n); });
    }
    std::filesystem::resize_file(cut, std::filesystem::file_size(cut) / 2);
    const auto kind = errorKindOf({.paths = {cut}}, &message);
    EXPECT_TRUE(kind == ErrorKind::CorruptFile || kind == ErrorKind::UnsupportedFormat) << message;
    EXPECT_NE(message.find("cut.nc"), std::string::npos) << message;
}

// A classic file (CDF-1, CDF-2, CDF-5) cut inside its data: netCDF-C once read the missing end
// as zeros, with exit 0, as long as the file held more bytes than all its values together.
// The size the header implies (where each variable's values begin, plus their size; records
// times the record size) is checked before a value is read.
TEST(NetcdfReader, ClassicFilesCutInsideTheirDataAreRefusedNamingBothSizes) {
    test::TempDir dir;
    struct Flavour {
        const char* name;
        int mode;
    };
    enum class Layout { Fixed, OneRecordVariable, TwoRecordVariables };
    for (const Flavour flavour :
         {Flavour{"cdf1", NC_CLOBBER}, Flavour{"cdf2", NC_CLOBBER | NC_64BIT_OFFSET},
          Flavour{"cdf5", NC_CLOBBER | NC_64BIT_DATA}}) {
        for (const Layout layout :
             {Layout::Fixed, Layout::OneRecordVariable, Layout::TwoRecordVariables}) {
            const std::string path = dir.file(std::string(flavour.name) + "_" +
                                              std::to_string(static_cast<int>(layout)) + ".nc");
            {
                // Shorts, 27 a member (54 bytes, not a multiple of 4): padding counts.
                int nc = -1, member = -1, s = -1, t = -1;
                std::array<int, 4> dims{};
                ASSERT_EQ(nc_create(path.c_str(), flavour.mode, &nc), NC_NOERR);
                nc_def_dim(nc, "member", layout == Layout::Fixed ? 2 : NC_UNLIMITED, &member);
                dims[0] = member;
                nc_def_dim(nc, "z", 3, &dims[1]);
                nc_def_dim(nc, "y", 3, &dims[2]);
                nc_def_dim(nc, "x", 3, &dims[3]);
                nc_def_var(nc, "s", NC_SHORT, 4, dims.data(), &s);
                if (layout != Layout::OneRecordVariable) {
                    nc_def_var(nc, "t", NC_FLOAT, 4, dims.data(), &t);
                }
                ASSERT_EQ(nc_enddef(nc), NC_NOERR);
                const std::array<std::size_t, 4> start{0, 0, 0, 0}, count{2, 3, 3, 3};
                std::vector<double> values(54);
                for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<double>(i);
                EXPECT_EQ(nc_put_vara_double(nc, s, start.data(), count.data(), values.data()),
                          NC_NOERR);
                if (t >= 0) {
                    EXPECT_EQ(nc_put_vara_double(nc, t, start.data(), count.data(), values.data()),
                              NC_NOERR);
                }
                ASSERT_EQ(nc_close(nc), NC_NOERR);
            }
            const auto size = std::filesystem::file_size(path);
            const data::DataSelection intact{
                .paths = {path}, .variable = "s", .memberDimension = "member"};
            const data::Ensemble e = data::openEnsemble(intact);
            ASSERT_EQ(e.memberCount(), 2u) << path;
            EXPECT_EQ(e.members[1].values[26], 53.0F) << path;

            // One byte short, and a few hundred: both less than the header, so more bytes are
            // left than all the values need together.
            for (const std::uintmax_t cut : {std::uintmax_t{1}, std::uintmax_t{size / 4}}) {
                const std::string copy = path + ".cut";
                std::filesystem::copy_file(path, copy,
                                           std::filesystem::copy_options::overwrite_existing);
                std::filesystem::resize_file(copy, size - cut);
                std::string message;
                data::DataSelection cutSelection = intact;
                cutSelection.paths = {copy};
                EXPECT_EQ(errorKindOf(cutSelection, &message), ErrorKind::CorruptFile) << copy;
                EXPECT_NE(message.find("'" + copy + "' is truncated"), std::string::npos)
                    << message;
                EXPECT_NE(message.find(std::to_string(size - cut) + " bytes"), std::string::npos)
                    << message;
                EXPECT_NE(message.find(std::to_string(size)), std::string::npos) << message;
                // The variable whose values it cuts is named.
                EXPECT_NE(message.find(layout == Layout::OneRecordVariable ? "'s'" : "'t'"),
                          std::string::npos)
                    << message;
            }
        }
    }
}

TEST(NetcdfReader, NoMemberDimensionListsTheDimensionsAndSuggestsOne) {
    test::TempDir dir;
    const std::string path = dir.file("forecast.nc");
    {
        NcTestFile f(path);
        const int t = f.dim("frtime", 3, range(3, 0, 12), {{"units", "hours"}});
        const int z = f.dim("level", 2, {1000, 500}, {{"units", "millibars"}});
        const int y = f.dim("lat", 2, range(2));
        const int x = f.dim("lon", 2, range(2));
        const int v = f.variable("T", NC_FLOAT, {t, z, y, x});
        f.write(v, 24, [](std::size_t n) { return static_cast<double>(n); });
    }
    std::string message;
    EXPECT_EQ(errorKindOf({.paths = {path}}, &message), ErrorKind::MemberDimensionNotFound);
    EXPECT_NE(message.find("frtime (3)"), std::string::npos) << message;
    EXPECT_NE(message.find("--member-dim frtime"), std::string::npos) << message;
    try {
        (void)data::describeEnsemble({.paths = {path}});
    } catch (const data::Error& e) {
        EXPECT_EQ(e.choices(), std::vector<std::string>{"frtime"}) << "level, lat, lon are spatial";
    }

    const data::Ensemble e = data::openEnsemble({.paths = {path}, .memberDimension = "frtime"});
    ASSERT_EQ(e.memberCount(), 3u);
    EXPECT_EQ(e.members[2].name, "frtime 24");
    EXPECT_FLOAT_EQ(e.members[2].values[0], 16.0F);

    EXPECT_EQ(errorKindOf({.paths = {path}, .memberDimension = "depth"}, &message),
              ErrorKind::NotThreeDimensional);
    EXPECT_NE(message.find("'depth'"), std::string::npos) << message;
}

TEST(NetcdfReader, TwoDimensionalAndAllMissingDataAreRefused) {
    test::TempDir dir;
    const std::string flat = dir.file("flat.nc");
    {
        NcTestFile f(flat);
        const int m = f.dim("realization", 2);
        const int y = f.dim("latitude", 3, range(3), {{"standard_name", "latitude"}});
        const int x = f.dim("longitude", 3, range(3), {{"standard_name", "longitude"}});
        const int v = f.variable("tas", NC_FLOAT, {m, y, x});
        f.write(v, 18, [](std::size_t) { return 1.0; });
    }
    std::string message;
    EXPECT_EQ(errorKindOf({.paths = {flat}}, &message), ErrorKind::NotThreeDimensional);
    EXPECT_NE(message.find("no vertical"), std::string::npos) << message;

    const std::string empty = dir.file("empty.nc");
    {
        NcTestFile f(empty);
        const int m = f.dim("member", 2);
        const int z = f.dim("z", 2), y = f.dim("y", 2), x = f.dim("x", 2);
        const int v = f.variable("a", NC_FLOAT, {m, z, y, x});
        f.number(v, "_FillValue", NC_FLOAT, {-1.0});
        f.write(v, 16, [](std::size_t) { return -1.0; });
    }
    EXPECT_EQ(errorKindOf({.paths = {empty}}, &message), ErrorKind::AllValuesMissing);
}

// A netCDF-4 variable declared at 30 x 100 x 1000 x 2500 floats (28 GiB) with no chunk ever
// written: the file's own metadata says so before anything is read or allocated, and both
// describing (`ensil info`) and opening refuse it, naming the file, the variable and its size.
// Before, opening read 28 GiB of fill values for minutes, past 12 GiB of memory.
TEST(NetcdfReader, AVariableWhoseValuesWereNeverWrittenIsRefusedBeforeAnythingIsRead) {
    test::TempDir dir;
    const std::string path = dir.file("declared_only.nc");
    {
        NcTestFile f(path);
        const int m = f.dim("member", 30);
        const int z = f.dim("level", 100, range(100));
        const int y = f.dim("lat", 1000);
        const int x = f.dim("lon", 2500);
        f.variable("t", NC_FLOAT, {m, z, y, x});
        f.endDefinitions();
    }
    ASSERT_LT(std::filesystem::file_size(path), 100000u);
    for (const bool describeOnly : {true, false}) {
        std::string message;
        try {
            if (describeOnly) {
                (void)data::describeEnsemble({.paths = {path}});
            } else {
                (void)data::openEnsemble({.paths = {path}});
            }
            ADD_FAILURE() << "accepted a file that holds no values";
        } catch (const data::Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::AllValuesMissing) << e.what();
            message = e.what();
        }
        EXPECT_NE(message.find("declared_only.nc', variable 't' (member, level, lat, lon) "
                               "holds no values: its 27.94 GiB are declared"),
                  std::string::npos)
            << message;
    }
}

// A file named twice, even through another path, is refused: it would be two identical
// members. Describing (`ensil info`) and opening say so, naming both spellings.
TEST(EnsembleReader, AFileNamedTwiceIsRefusedNotReadAsTwoMembers) {
    test::TempDir dir;
    const std::string path = writeStandard(dir, "member");
    const std::string again = dir.file(".") + "/member.nc";
    std::string message;
    EXPECT_EQ(errorKindOf({.paths = {path, again}}, &message), ErrorKind::InvalidArgument);
    EXPECT_NE(message.find("' is given twice (also as '" + again + "')"), std::string::npos)
        << message;
    EXPECT_THROW((void)data::describeEnsemble({.paths = {path, path}}), data::Error);
}

// One member per file, the files valid at different times (two GFS runs a season apart):
// they are still read, but a warning names both files and both times, and the step's label,
// which the picture's title shows, says that the members' times differ.
TEST(EnsembleReader, MemberFilesOfDifferentTimesAreNamedInAWarningAndTheLabel) {
    test::TempDir dir;
    const auto write = [&](const std::string& name, const std::string& since) {
        const std::string path = dir.file(name);
        NcTestFile f(path);
        const int t = f.dim("time", 1, {0.0}, {{"units", "hours since " + since}});
        const int z = f.dim("level", 3, range(3));
        const int y = f.dim("lat", 4, range(4), {{"units", "degrees_north"}});
        const int x = f.dim("lon", 5, range(5), {{"units", "degrees_east"}});
        const int v = f.variable("t", NC_FLOAT, {t, z, y, x});
        f.write(v, 60, [](std::size_t n) { return static_cast<double>(n); });
        return path;
    };
    const std::string january = write("gfs_a.nc", "2011-01-15 12:00:00");
    const std::string october = write("gfs_b.nc", "2011-10-11 00:00:00");
    const std::string alsoJanuary = write("gfs_c.nc", "2011-01-15 12:00:00");
    const data::EnsembleDescription same =
        data::describeEnsemble({.paths = {january, alsoJanuary}});
    EXPECT_TRUE(same.warnings.empty());
    ASSERT_EQ(same.timeSteps.count(), 1u);
    EXPECT_EQ(same.timeSteps.labels[0].find("differ"), std::string::npos);

    const data::EnsembleDescription d = data::describeEnsemble({.paths = {january, october}});
    EXPECT_EQ(d.members, 2u);
    ASSERT_EQ(d.warnings.size(), 1u);
    const std::string& w = d.warnings.front();
    EXPECT_NE(w.find("'" + october + "' is at time 2011-10-11"), std::string::npos) << w;
    EXPECT_NE(w.find("where '" + january + "' is at 2011-01-15"), std::string::npos) << w;
    ASSERT_EQ(d.timeSteps.count(), 1u);
    EXPECT_TRUE(d.timeSteps.labels[0].starts_with("2011-01-15")) << d.timeSteps.labels[0];
    EXPECT_TRUE(d.timeSteps.labels[0].ends_with("(members' times differ)"))
        << d.timeSteps.labels[0];
}

TEST(NetcdfReader, TimeIndexSelectsAndIsChecked) {
    test::TempDir dir;
    const std::string path = dir.file("times.nc");
    {
        NcTestFile f(path);
        const int m = f.dim("number", 2);
        const int t = f.dim("time", 3, range(3, 0, 6), {{"units", "hours since 2020-02-28 12:00"}});
        const int z = f.dim("plev", 2, {85000, 50000}, {{"units", "Pa"}});
        const int y = f.dim("lat", 2, range(2)), x = f.dim("lon", 2, range(2));
        const int v = f.variable("z", NC_FLOAT, {m, t, z, y, x});
        f.write(v, 48, [](std::size_t n) { return static_cast<double>(n); });
    }
    const data::EnsembleDescription d = data::describeEnsemble({.paths = {path}, .timeIndex = 2});
    ASSERT_EQ(d.fixedDimensions.size(), 1u);
    EXPECT_EQ(d.fixedDimensions[0], "time = 2 of 3 (2020-02-29T00:00)");  // leap day
    const data::Ensemble e = data::openEnsemble({.paths = {path}, .timeIndex = 2});
    EXPECT_FLOAT_EQ(e.members[1].values[0], 24.0F + 16.0F);
    std::string message;
    EXPECT_EQ(errorKindOf({.paths = {path}, .timeIndex = 3}, &message), ErrorKind::InvalidArgument);
    EXPECT_NE(message.find("0 to 2"), std::string::npos) << message;
}

TEST(NetcdfReader, TimeStepsAreDatedAlongTheFirstFixedDimensionAndAsManyAsTheShortest) {
    test::TempDir dir;
    const std::string dated = dir.file("dated.nc"), undated = dir.file("undated.nc");
    {
        NcTestFile f(dated);
        const int m = f.dim("number", 2);
        const int t = f.dim("time", 3, range(3, 0, 6), {{"units", "hours since 2020-02-28 12:00"}});
        const int z = f.dim("plev", 2, {85000, 50000}, {{"units", "Pa"}});
        const int y = f.dim("lat", 2, range(2)), x = f.dim("lon", 2, range(2));
        const int v = f.variable("z", NC_FLOAT, {m, t, z, y, x});
        f.write(v, 48, [](std::size_t n) { return static_cast<double>(n); });
    }
    const data::TimeSteps expected{
        .dimension = "time",
        .labels = {"2020-02-28T12:00", "2020-02-28T18:00", "2020-02-29T00:00"}};
    EXPECT_EQ(data::describeEnsemble({.paths = {dated}, .timeIndex = 1}).timeSteps, expected);
    EXPECT_EQ(data::openEnsemble({.paths = {dated}}).timeSteps, expected) << "copied on reading";
    {
        // Two fixed dimensions: the one index runs along both, so the shorter (2) bounds it; a
        // coordinate that is not a date labels nothing, the index does.
        NcTestFile f(undated);
        const int m = f.dim("number", 2);
        const int s = f.dim("step", 3, {6, 12, 18}, {{"units", "hours"}});
        const int r = f.dim("run", 2);
        const int z = f.dim("plev", 2, {85000, 50000}, {{"units", "Pa"}});
        const int y = f.dim("lat", 2, range(2)), x = f.dim("lon", 2, range(2));
        const int v = f.variable("z", NC_FLOAT, {m, s, r, z, y, x});
        f.write(v, 96, [](std::size_t n) { return static_cast<double>(n); });
    }
    EXPECT_EQ(data::describeEnsemble({.paths = {undated}}).timeSteps,
              (data::TimeSteps{.dimension = "step", .labels = {"0", "1"}}));
    // Without fixed dimensions there are no steps.
    const std::string plain = dir.file("plain.nc");
    {
        NcTestFile f(plain);
        const int m = f.dim("number", 2);
        const int z = f.dim("plev", 2, {85000, 50000}, {{"units", "Pa"}});
        const int y = f.dim("lat", 2, range(2)), x = f.dim("lon", 2, range(2));
        const int v = f.variable("z", NC_FLOAT, {m, z, y, x});
        f.write(v, 16, [](std::size_t n) { return static_cast<double>(n); });
    }
    EXPECT_EQ(data::describeEnsemble({.paths = {plain}}).timeSteps, data::TimeSteps{});
}

TEST(NetcdfReader, CancelStopsBetweenMembersAndProgressIsMonotonic) {
    test::TempDir dir;
    const std::string path = writeStandard(dir, "member");
    std::vector<double> seen;
    (void)data::openEnsemble({.paths = {path}}, {}, [&](double f) { seen.push_back(f); });
    ASSERT_EQ(seen.size(), 3u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);

    std::stop_source stop;
    EXPECT_THROW((void)data::openEnsemble({.paths = {path}}, stop.get_token(),
                                          [&](double) { stop.request_stop(); }),
                 data::Cancelled);
}

TEST(EnsembleReader, RefusesWhatWillNotFitInMemory) {
    try {
        data::checkMemoryFor(std::size_t{1} << 60, "the test ensemble");
        FAIL() << "an exabyte was accepted";
    } catch (const data::Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::OutOfMemory);
        EXPECT_NE(std::string(e.what()).find("GiB"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(data::checkMemoryFor(1024, "a kilobyte"));
}

TEST(EnsembleReader, SourceIdentityChangesWhenTheFileOrSelectionDoes) {
    test::TempDir dir;
    const std::string path = writeStandard(dir, "member");
    const data::DataSelection s{.paths = {path}};
    const std::string before = data::sourceIdentity(s);
    EXPECT_EQ(before, data::sourceIdentity(s));
    data::DataSelection other = s;
    other.timeIndex = 1;
    EXPECT_NE(before, data::sourceIdentity(other));
    std::filesystem::last_write_time(
        path, std::filesystem::last_write_time(path) + std::chrono::seconds(5));
    EXPECT_NE(before, data::sourceIdentity(s)) << "a rewritten file is another source";
}

TEST(NetcdfReader, WithoutVarTheVariableWithTheMostLevelsIsChosenTheFirstAmongEquals) {
    // A two-level field first in the file, a five-level one after it: without --var the one
    // with more 3D structure is drawn.
    test::TempDir dir;
    const std::string path = dir.file("levels.nc");
    {
        NcTestFile f(path);
        const int m = f.dim("member", 3, range(3));
        const int thin = f.dim("plev", 2, {850, 500}, {{"units", "hPa"}});
        const int deep = f.dim("level", 5, {1000, 850, 700, 500, 300}, {{"units", "hPa"}});
        const int y = f.dim("lat", 4, range(4, 30, 5), {{"units", "degrees_north"}});
        const int x = f.dim("lon", 4, range(4, -10, 2), {{"units", "degrees_east"}});
        const int a = f.variable("sheet", NC_FLOAT, {m, thin, y, x});
        const int b = f.variable("deep", NC_FLOAT, {m, deep, y, x});
        const int c = f.variable("deep_too", NC_FLOAT, {m, deep, y, x});
        f.write(a, 3 * 2 * 16, [](std::size_t n) { return double(n); });
        f.write(b, 3 * 5 * 16, [](std::size_t n) { return double(n); });
        f.write(c, 3 * 5 * 16, [](std::size_t n) { return double(n); });
    }
    EXPECT_EQ(data::describeEnsemble({.paths = {path}}).variable, "deep");
    EXPECT_EQ(data::describeEnsemble({.paths = {path}, .variable = "sheet"}).variable, "sheet");
}

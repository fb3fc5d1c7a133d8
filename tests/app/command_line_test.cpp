#include "cli/command_line.h"

#include <gtest/gtest.h>
#include <netcdf.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QString>
#include <QTextStream>

#include "cli/generate_command.h"
#include "tests/support/temp_dir.h"

using namespace ensil::cli;

namespace {
struct CliRun {
    int code = 0;
    bool workbench = false;
    QStringList paths;
    QString variable, memberDim;
    std::size_t timeIndex = 0;
    std::size_t memoryLimit = 0;
    QString out, err;
};

CliRun run(QStringList args) {
    args.prepend("ensil");
    CliRun r;
    QTextStream out(&r.out), err(&r.err);
    const CommandLineOutcome o = runCommandLine(args, out, err);
    out.flush();
    err.flush();
    r.code = o.exitCode;
    r.workbench = o.workbench.has_value();
    if (o.workbench) {
        for (const auto& p : o.workbench->selection.paths) r.paths << QString::fromStdString(p);
        r.variable = QString::fromStdString(o.workbench->selection.variable);
        r.memberDim = QString::fromStdString(o.workbench->selection.memberDimension);
        r.timeIndex = o.workbench->selection.timeIndex;
        r.memoryLimit = o.workbench->memoryLimit;
    }
    return r;
}
}  // namespace

// -V and --version name ensil's version, then every library it reads and draws with, as it
// runs them, and the compiler: what a bug report needs. netCDF's and PROJ's own tools agree.
TEST(CommandLine, VersionNamesTheLibrariesAsTheyRunAndTheCompiler) {
    const CliRun version = run({"-V"});
    EXPECT_EQ(version.code, 0);
    EXPECT_EQ(run({"--version"}).out, version.out);
    const std::string text = version.out.toStdString();
    for (const char* library : {"Qt", "netCDF", "HDF5", "ecCodes", "PROJ", "VTK", "xxHash"}) {
        const QRegularExpression named(
            QStringLiteral("[ ,]%1 [0-9]+\\.[0-9]+\\.[0-9]+").arg(QLatin1String(library)));
        EXPECT_TRUE(version.out.contains(named)) << library << " in:\n" << text;
    }
    const auto toolSays = [](const QString& tool, const QStringList& args) {
        QProcess process;
        process.start(tool, args);
        EXPECT_TRUE(process.waitForFinished(30000)) << tool.toStdString();
        return QString::fromLocal8Bit(process.readAllStandardOutput()).trimmed();
    };
    const QString netcdf = toolSays(QStringLiteral("nc-config"), {QStringLiteral("--version")});
    EXPECT_TRUE(netcdf.startsWith(QLatin1String("netCDF ")) && version.out.contains(netcdf))
        << netcdf.toStdString() << " in:\n"
        << text;
    const QString proj = toolSays(QStringLiteral("pkg-config"),
                                  {QStringLiteral("--modversion"), QStringLiteral("proj")});
    EXPECT_TRUE(!proj.isEmpty() && version.out.contains(QStringLiteral("PROJ ") + proj))
        << proj.toStdString() << " in:\n"
        << text;
    EXPECT_TRUE(version.out.contains(QLatin1String("\nbuilt with "))) << text;
    // -v is not the version: most tools read it as "verbose".
    EXPECT_EQ(run({"-v"}).code, 2);
}

TEST(CommandLine, VersionAndHelpNeedNoDisplay) {
    EXPECT_TRUE(isHeadlessInvocation({"ensil", "--version"}));
    EXPECT_TRUE(isHeadlessInvocation({"ensil", "generate", "--out", "x.nc"}));
    EXPECT_FALSE(isHeadlessInvocation({"ensil"}));
    EXPECT_FALSE(isHeadlessInvocation({"ensil", "data.nc"}));

    const CliRun version = run({"--version"});
    EXPECT_EQ(version.code, 0);
    EXPECT_TRUE(version.out.startsWith("ensil 0.")) << version.out.toStdString();
    EXPECT_FALSE(version.workbench);

    const CliRun help = run({"--help"});
    EXPECT_EQ(help.code, 0);
    for (const char* sub : {"generate", "info", "preprocess", "render"}) {
        EXPECT_TRUE(help.out.contains(sub)) << sub;
    }
}

TEST(CommandLine, NoArgumentsOpensTheDemoAndPathsAreForwarded) {
    const CliRun demo = run({});
    EXPECT_TRUE(demo.workbench);
    EXPECT_TRUE(demo.paths.isEmpty());
    const CliRun files = run({"a.nc", "b.nc"});
    EXPECT_TRUE(files.workbench);
    EXPECT_EQ(files.paths, (QStringList{"a.nc", "b.nc"}));
    const CliRun chosen = run({"t.nc", "--var", "u", "--member-dim", "month", "--time-index", "2"});
    EXPECT_TRUE(chosen.workbench);
    EXPECT_EQ(chosen.variable, "u");
    EXPECT_EQ(chosen.memberDim, "month");
    EXPECT_EQ(chosen.timeIndex, 2u);
    const CliRun bad = run({"t.nc", "--time-index", "-1"});
    EXPECT_EQ(bad.code, 2);
    EXPECT_FALSE(bad.workbench);
}

TEST(CommandLine, TheWorkbenchTakesAMemoryLimit) {
    EXPECT_EQ(run({"t.nc"}).memoryLimit, 0u) << "the default, chosen when data are opened";
    const CliRun limited = run({"t.nc", "--memory-limit", "512M"});
    EXPECT_TRUE(limited.workbench);
    EXPECT_EQ(limited.memoryLimit, std::size_t{512} << 20);
    EXPECT_EQ(run({"--memory-limit", "1GiB"}).memoryLimit, std::size_t{1} << 30);
    const CliRun bad = run({"t.nc", "--memory-limit", "lots"});
    EXPECT_EQ(bad.code, 2);
    EXPECT_FALSE(bad.workbench);
    EXPECT_TRUE(bad.err.contains("--memory-limit 'lots' is not a size")) << bad.err.toStdString();
    EXPECT_TRUE(run({"--help"}).out.contains("--memory-limit")) << "said in the help";
}

TEST(CommandLine, UnknownOptionIsAnErrorWithAHint) {
    const CliRun r = run({"--frobnicate"});
    EXPECT_EQ(r.code, 2);
    EXPECT_FALSE(r.workbench);
    EXPECT_TRUE(r.err.contains("--help")) << r.err.toStdString();
}

TEST(CommandLine, RenderExplainsMissingArguments) {
    const CliRun noOut = run({"render", "--demo"});
    EXPECT_EQ(noOut.code, 2);
    EXPECT_TRUE(noOut.err.contains("--out")) << noOut.err.toStdString();
    const CliRun plane =
        run({"render", "--demo", "--iso", "30", "--out", "y.png", "--plane", "1,2"});
    EXPECT_EQ(plane.code, 2);
    EXPECT_TRUE(plane.err.contains("NX,NY,NZ,OFFSET")) << plane.err.toStdString();
}

TEST(GenerateCommand, WritesTheRequestedEnsemble) {
    ensil::test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("demo.nc"));
    const CliRun r =
        run({"generate", "--members", "6", "--grid", "20x10x5", "--seed", "9", "--out", path});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains("6 members")) << r.out.toStdString();

    int nc = -1;
    ASSERT_EQ(nc_open(path.toLocal8Bit().constData(), NC_NOWRITE, &nc), NC_NOERR);
    const auto dimSize = [nc](const char* name) {
        int id = -1;
        std::size_t n = 0;
        nc_inq_dimid(nc, name, &id);
        nc_inq_dimlen(nc, id, &n);
        return n;
    };
    EXPECT_EQ(dimSize("number"), 6u);
    EXPECT_EQ(dimSize("lon"), 20u);
    EXPECT_EQ(dimSize("lat"), 10u);
    EXPECT_EQ(dimSize("plev"), 5u);
    nc_close(nc);
}

TEST(GenerateCommand, BadArgumentsAreExplained) {
    const CliRun noOut = run({"generate"});
    EXPECT_EQ(noOut.code, 2);
    EXPECT_TRUE(noOut.err.contains("--out")) << noOut.err.toStdString();
    const CliRun badGrid = run({"generate", "--grid", "12x4", "--out", "x.nc"});
    EXPECT_EQ(badGrid.code, 2);
    EXPECT_TRUE(badGrid.err.contains("256x128x16")) << badGrid.err.toStdString();
    const CliRun badMembers = run({"generate", "--members", "zero", "--out", "x.nc"});
    EXPECT_EQ(badMembers.code, 2);
    const CliRun unwritable = run(
        {"generate", "--members", "2", "--grid", "4x4x2", "--out", "/nonexistent-ensil-dir/x.nc"});
    EXPECT_EQ(unwritable.code, 1);
    EXPECT_TRUE(unwritable.err.contains("/nonexistent-ensil-dir/x.nc"))
        << unwritable.err.toStdString();
}

TEST(GenerateCommand, GridSizeParsing) {
    std::size_t nx = 0, ny = 0, nz = 0;
    EXPECT_TRUE(parseGridSize("128x256x16", nx, ny, nz));
    EXPECT_EQ(nx, 128u);
    EXPECT_EQ(ny, 256u);
    EXPECT_EQ(nz, 16u);
    EXPECT_FALSE(parseGridSize("128x256", nx, ny, nz));
    EXPECT_FALSE(parseGridSize("1x256x16", nx, ny, nz));
    EXPECT_FALSE(parseGridSize("axbxc", nx, ny, nz));
    EXPECT_EQ(nx, 128u) << "a failed parse leaves the outputs alone";
}

// `ensil info --json` says where the grid lies: uk_hires's rotated pole and its true domain
// (checked to 0.05 degrees against the rotation written out in tests/geo/domain_bounds_test),
// ERA5's plain longitude/latitude axes, and null for a volume with no geography.
TEST(InfoCommand, JsonReportsTheGridMappingAndTheTrueLongitudeLatitudeBounds) {
    const QString real = QStringLiteral(ENSIL_SHARED_DATA_DIR "/");
    const auto json = [](const CliRun& r) {
        return QJsonDocument::fromJson(r.out.toUtf8()).object();
    };

    const CliRun uk = run({"info", real + "uk_hires.nc", "--member-dim", "time", "--json"});
    ASSERT_EQ(uk.code, 0) << uk.err.toStdString();
    EXPECT_EQ(json(uk)["grid_mapping"].toString(), "rotated_latitude_longitude");
    const QJsonArray b = json(uk)["lon_lat_bounds"].toArray();
    ASSERT_EQ(b.size(), 4);
    EXPECT_NEAR(b[0].toDouble(), -6.90, 0.05);
    EXPECT_NEAR(b[1].toDouble(), -2.49, 0.05);
    EXPECT_NEAR(b[2].toDouble(), 52.57, 0.05);
    EXPECT_NEAR(b[3].toDouble(), 55.38, 0.05);

    const CliRun era5 = run({"info", real + "era5_eda_members.nc", "--json"});
    ASSERT_EQ(era5.code, 0);
    EXPECT_TRUE(json(era5)["grid_mapping"].isNull());
    EXPECT_EQ(json(era5)["lon_lat_bounds"].toArray(), (QJsonArray{0.0, 357.0, -90.0, 90.0}));

    const CliRun volume = run({"info", real + "ironProt.vtk", "--json"});
    ASSERT_EQ(volume.code, 0);
    EXPECT_TRUE(json(volume)["grid_mapping"].isNull());
    EXPECT_TRUE(json(volume)["lon_lat_bounds"].isNull());
}

// --levels keeps the vertical levels between its ends, in units UDUNITS-2 converts to the
// axis's (ERA-Interim's levels are in millibars; the range in hPa), for info as for every
// command that reads; a malformed range is a usage error (2), one that keeps fewer than two
// levels a data error (1), each saying why.
TEST(InfoCommand, LevelsKeepTheVerticalLevelsBetweenTheirEndsInAnyPressureUnits) {
    const QString file = QStringLiteral(ENSIL_SHARED_DATA_DIR "/eraint_uvz.nc");
    const auto json = [](const CliRun& r) {
        return QJsonDocument::fromJson(r.out.toUtf8()).object();
    };
    const CliRun all = run({"info", file, "--member-dim", "month", "--json"});
    ASSERT_EQ(all.code, 0) << all.err.toStdString();
    EXPECT_EQ(json(all)["grid"].toArray()[2].toInt(), 3);
    EXPECT_FALSE(json(all).contains("kept_levels"));

    const CliRun upper =
        run({"info", file, "--member-dim", "month", "--levels", "500:200hPa", "--json"});
    ASSERT_EQ(upper.code, 0) << upper.err.toStdString();
    EXPECT_EQ(json(upper)["grid"].toArray()[2].toInt(), 2);
    const QJsonObject z = json(upper)["axes"].toArray()[2].toObject();
    EXPECT_DOUBLE_EQ(z["first"].toDouble(), 200.0);
    EXPECT_DOUBLE_EQ(z["last"].toDouble(), 500.0);
    EXPECT_EQ(json(upper)["kept_levels"].toObject(),
              (QJsonObject{{"first", 0}, {"count", 2}, {"of", 3}}));
    const CliRun text = run({"info", file, "--member-dim", "month", "--levels", "50000:20000 Pa"});
    EXPECT_TRUE(text.out.contains("levels 1 to 2 of the file's 3 kept")) << text.out.toStdString();

    const CliRun malformed = run({"info", file, "--member-dim", "month", "--levels", "500-200"});
    EXPECT_EQ(malformed.code, 2);
    EXPECT_TRUE(malformed.err.contains("--levels: the level range '500-200'"))
        << malformed.err.toStdString();
    const CliRun one = run({"info", file, "--member-dim", "month", "--levels", "600:400hPa"});
    EXPECT_EQ(one.code, 1);
    EXPECT_TRUE(one.err.contains("hold 1 level of the vertical axis 'level'"))
        << one.err.toStdString();
}

// --bbox keeps the columns and rows within a box, here across the 0/360 seam of ERA5's 0..357
// grid (3 degrees: 351..357 written as -9..-3, then 0..39; 72 N down to 36 N), and info says
// which (--json: kept_region). A malformed box, and one with no grid point, are usage errors (2)
// on every command that reads, the latter naming the grid's extent; a grid that is not
// longitude-latitude is a data error (1) naming the file.
TEST(InfoCommand, BboxKeepsARegionAcrossTheSeamAndABoxWithoutPointsIsAUsageError) {
    const QString file = QStringLiteral(ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc");
    const auto json = [](const CliRun& r) {
        return QJsonDocument::fromJson(r.out.toUtf8()).object();
    };
    const CliRun europe = run({"info", file, "--var", "t", "--bbox", "-10,40,35,72", "--json"});
    ASSERT_EQ(europe.code, 0) << europe.err.toStdString();
    EXPECT_EQ(json(europe)["grid"].toArray(), (QJsonArray{17, 13, 2}));
    const QJsonObject x = json(europe)["axes"].toArray()[0].toObject();
    EXPECT_DOUBLE_EQ(x["first"].toDouble(), -9.0);
    EXPECT_DOUBLE_EQ(x["last"].toDouble(), 39.0);
    const QJsonObject y = json(europe)["axes"].toArray()[1].toObject();
    EXPECT_DOUBLE_EQ(y["first"].toDouble(), 72.0);
    EXPECT_DOUBLE_EQ(y["last"].toDouble(), 36.0);
    EXPECT_EQ(json(europe)["kept_region"].toObject(),
              (QJsonObject{{"bbox", QJsonArray{-10, 40, 35, 72}},
                           {"columns", 17},
                           {"rows", 13},
                           {"of", QJsonArray{120, 61}},
                           {"column_runs", QJsonArray{QJsonObject{{"first", 117}, {"count", 3}},
                                                      QJsonObject{{"first", 0}, {"count", 14}}}},
                           {"first_row", 6}}));
    const CliRun whole = run({"info", file, "--var", "t", "--json"});
    EXPECT_FALSE(json(whole).contains("kept_region"));
    const CliRun text = run({"info", file, "--var", "t", "--bbox=350,40,72,35"});
    EXPECT_TRUE(text.out.contains(
        "region 350,40,72,35: 17 x 13 of the file's 120 x 61 columns and rows kept (--bbox)"))
        << text.out.toStdString();

    const CliRun malformed = run({"info", file, "--var", "t", "--bbox", "-10,40,35"});
    EXPECT_EQ(malformed.code, 2);
    EXPECT_TRUE(malformed.err.contains("--bbox: the region '-10,40,35' has 3 values"))
        << malformed.err.toStdString();

    const ensil::test::TempDir dir;
    const QString extent = QStringLiteral(
                               "the region 1,2,35,72 holds no grid point of 't' in %1, whose grid "
                               "spans longitudes 0 to "
                               "357 and latitudes 90 to -90 (120 x 61 points)")
                               .arg(file);
    for (const QStringList& command : {QStringList{"info"}, QStringList{"preprocess", "--no-cache"},
                                       QStringList{"stats", "--iso", "260", "--out",
                                                   QString::fromStdString(dir.file("s.nc"))}}) {
        const CliRun nothing =
            run(command + QStringList{file, "--var", "t", "--bbox", "1,2,35,72"});
        EXPECT_EQ(nothing.code, 2) << command.front().toStdString();
        EXPECT_TRUE(nothing.err.contains(extent)) << nothing.err.toStdString();
    }

    const QString rotatedFile = QStringLiteral(ENSIL_SHARED_DATA_DIR "/uk_hires.nc");
    const CliRun rotated =
        run({"info", rotatedFile, "--member-dim", "time", "--bbox", "-5,0,50,55"});
    EXPECT_EQ(rotated.code, 1);
    EXPECT_TRUE(rotated.err.contains("uk_hires.nc: it lies on a 'rotated_latitude_longitude' grid"))
        << rotated.err.toStdString();
}

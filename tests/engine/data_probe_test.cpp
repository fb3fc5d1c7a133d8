#include "engine/data_probe.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "data/demo_ensemble.h"
#include "data/netcdf_writer.h"
#include "engine/streaming_run.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {
data::DataSelection fileSelection(const std::string& name) {
    data::DataSelection s;
    s.paths = {std::string(ENSIL_SHARED_DATA_DIR "/") + name};
    return s;
}

const engine::ProbedVariable* findVariable(const engine::DataProbe& probe, const QString& name) {
    for (const auto& v : probe.variables) {
        if (v.name == name) return &v;
    }
    return nullptr;
}
}  // namespace

TEST(DataProbe, DescribesARealEnsembleFileFromItsHeaders) {
    data::DataSelection selection = fileSelection("era5_eda_members.nc");
    selection.variable = "t";
    const engine::DataProbe probe = engine::probeData(selection);
    ASSERT_TRUE(probe.error.isEmpty()) << probe.error.toStdString();
    EXPECT_TRUE(probe.format.startsWith("NetCDF")) << probe.format.toStdString();
    EXPECT_EQ(probe.variable, "t");
    const engine::ProbedVariable* t = findVariable(probe, "t");
    ASSERT_NE(t, nullptr);
    EXPECT_TRUE(t->usable);
    EXPECT_EQ(t->dimensions, "number=10, time=4, plev=2, lat=61, lon=120");
    EXPECT_EQ(t->units, "K");
    EXPECT_EQ(t->longName, "Temperature");
    EXPECT_EQ(probe.memberDimension, "number");
    EXPECT_FALSE(probe.memberDimensionReason.isEmpty());
    EXPECT_EQ(probe.memberDimensionChoices, (QStringList{"number", "time"}));
    EXPECT_EQ(probe.members, 10);
    EXPECT_EQ(probe.timeSteps, 4) << "time is held at one of its 4 indices";
    EXPECT_EQ(probe.grid, "120 x 61 x 2");
    ASSERT_EQ(probe.fixedDimensions.size(), 1);
    EXPECT_TRUE(probe.fixedDimensions.front().startsWith("time = 0 of 4"));
}

TEST(DataProbe, TheTimeIndexAndAnOverriddenMemberDimensionAreApplied) {
    data::DataSelection selection = fileSelection("era5_eda_members.nc");
    selection.variable = "z";
    selection.memberDimension = "time";
    selection.timeIndex = 7;
    const engine::DataProbe probe = engine::probeData(selection);
    ASSERT_TRUE(probe.error.isEmpty()) << probe.error.toStdString();
    EXPECT_EQ(probe.memberDimension, "time");
    EXPECT_EQ(probe.members, 4);
    EXPECT_EQ(probe.timeSteps, 10) << "now 'number' is the fixed dimension";
    EXPECT_TRUE(probe.fixedDimensions.front().startsWith("number = 7 of 10"));
}

TEST(DataProbe, AFileWithoutAMemberDimensionListsItsVariablesAndTheCandidates) {
    const engine::DataProbe probe = engine::probeData(fileSelection("contour.cdf"));
    EXPECT_FALSE(probe.error.isEmpty());
    EXPECT_TRUE(probe.error.contains("Choose the dimension")) << probe.error.toStdString();
    EXPECT_EQ(probe.memberDimensionChoices, QStringList{"frtime"});
    EXPECT_TRUE(probe.memberDimension.isEmpty());
    EXPECT_EQ(probe.members, 0);
    const engine::ProbedVariable* psl = findVariable(probe, "Psl");
    ASSERT_NE(psl, nullptr) << "the variables are listed even before the choice";
    EXPECT_FALSE(psl->usable);
    EXPECT_FALSE(psl->whyNotUsable.isEmpty());
    ASSERT_NE(findVariable(probe, "T"), nullptr);

    data::DataSelection chosen = fileSelection("contour.cdf");
    chosen.memberDimension = "frtime";
    chosen.variable = "T";
    const engine::DataProbe answered = engine::probeData(chosen);
    ASSERT_TRUE(answered.error.isEmpty()) << answered.error.toStdString();
    EXPECT_EQ(answered.members, 7);
    EXPECT_EQ(answered.memberDimension, "frtime");
}

TEST(DataProbe, AnEnsembleWithoutVerticalAxisIsExplained) {
    const engine::DataProbe probe =
        engine::probeData(fileSelection("glosea4_surface_temperature_ensemble.nc"));
    EXPECT_TRUE(probe.error.contains("no vertical")) << probe.error.toStdString();
}

TEST(DataProbe, GarbageBytesInANcFileGiveAReadableMessage) {
    test::TempDir dir;
    const std::string path = dir.file("garbage.nc");
    {
        std::ofstream out(path, std::ios::binary);
        std::mt19937 bytes(7);
        for (int i = 0; i < 4096; ++i) out.put(static_cast<char>(bytes() & 0xFF));
    }
    data::DataSelection selection;
    selection.paths = {path};
    const engine::DataProbe probe = engine::probeData(selection);
    EXPECT_TRUE(probe.variables.empty());
    EXPECT_TRUE(probe.error.contains("garbage.nc"))
        << "names the file: " << probe.error.toStdString();
    EXPECT_TRUE(probe.error.contains("not in a format ensil reads")) << probe.error.toStdString();

    // A NetCDF signature followed by garbage is a broken file, not a crash.
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out << "CDF\x01";
        std::mt19937 bytes(11);
        for (int i = 0; i < 4096; ++i) out.put(static_cast<char>(bytes() & 0xFF));
    }
    const engine::DataProbe broken = engine::probeData(selection);
    EXPECT_FALSE(broken.error.isEmpty());
    EXPECT_TRUE(broken.error.contains("garbage.nc")) << broken.error.toStdString();
}

TEST(DataProbe, AMissingFileIsNamed) {
    data::DataSelection selection;
    selection.paths = {"/nonexistent/run_01.nc"};
    const engine::DataProbe probe = engine::probeData(selection);
    EXPECT_TRUE(probe.error.contains("/nonexistent/run_01.nc")) << probe.error.toStdString();
}

TEST(DataProbe, VtkFilesAreOneMemberEachWithNothingToChooseAlong) {
    // Two member files: a copy, since the same file named twice is refused.
    data::DataSelection selection = fileSelection("ironProt.vtk");
    const test::TempDir dir;
    const std::string copy = dir.file("ironProt_copy.vtk");
    std::filesystem::copy_file(selection.paths.front(), copy);
    selection.paths.push_back(copy);
    const engine::DataProbe probe = engine::probeData(selection);
    ASSERT_TRUE(probe.error.isEmpty()) << probe.error.toStdString();
    EXPECT_EQ(probe.format, "VTK legacy");
    EXPECT_EQ(probe.variable, "scalars");
    EXPECT_EQ(probe.members, 2);
    EXPECT_TRUE(probe.memberDimension.isEmpty());
    EXPECT_TRUE(probe.memberDimensionChoices.isEmpty()) << "z, y and x are the grid's axes";
    EXPECT_EQ(probe.timeSteps, 0);
    EXPECT_EQ(probe.grid, "68 x 68 x 68");
}

TEST(DataProbe, SaysHowTheDataOpenWithinTheWorkbenchsMemoryBudget) {
    data::DataSelection era5 = fileSelection("era5_eda_members.nc");
    era5.variable = "t";
    EXPECT_TRUE(engine::probeData(era5).size.isEmpty()) << "not asked";
    EXPECT_EQ(engine::probeData(era5, std::size_t{1} << 30).size, "0.6 MiB of values");
    const QString tooSmall = engine::probeData(era5, std::size_t{1} << 19).size;
    EXPECT_TRUE(tooSmall.startsWith("0.6 MiB of values: a memory limit of"))
        << tooSmall.toStdString();

    // The demo (24 members, 97 x 96 x 25) within a budget its in-memory peak just misses.
    test::TempDir dir;
    const data::DataSelection demo{.paths = {dir.file("demo.nc")}};
    data::writeNetcdf(
        data::makeDemoEnsemble({.members = 24, .nx = 97, .ny = 96, .nz = 25}).ensemble,
        demo.paths.front());
    const std::size_t budget = engine::inMemoryPeakBytes(data::describeEnsemble(demo)) - 1;
    EXPECT_EQ(engine::probeData(demo, budget).size,
              "21 MiB of values, more than the memory budget of 32 MiB: read in slabs, a copy at "
              "every 2nd point in memory");
}

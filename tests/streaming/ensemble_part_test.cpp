// Hyperslab reads (data/ensemble_part.h): a part of an ensemble read alone equals the same part
// of the whole, and parts outside the data are refused before anything is read.
#include "data/ensemble_part.h"

#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <string>

#include "data/demo_ensemble.h"
#include "data/error.h"
#include "data/hdf5_reader.h"
#include "data/netcdf_writer.h"
#include "tests/data/netcdf_test_file.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {

// Every value of `part` equals the whole's at the same member and point.
void expectPartOfWhole(const data::Ensemble& part, const data::Ensemble& whole,
                       const data::EnsemblePart& at) {
    ASSERT_EQ(part.memberCount(), at.memberCount);
    ASSERT_EQ(part.grid.nz(), at.layerCount);
    ASSERT_EQ(part.grid.nx(), whole.grid.nx());
    ASSERT_EQ(part.grid.ny(), whole.grid.ny());
    for (std::size_t k = 0; k < at.layerCount; ++k) {
        EXPECT_EQ(part.grid.z().values[k], whole.grid.z().values[at.firstLayer + k]);
    }
    for (std::size_t m = 0; m < at.memberCount; ++m) {
        const data::Member& got = part.members[m];
        const data::Member& want = whole.members[at.firstMember + m];
        EXPECT_EQ(got.name, want.name);
        ASSERT_EQ(got.values.size(), part.grid.pointCount());
        std::size_t differ = 0;
        for (std::size_t k = 0; k < at.layerCount; ++k) {
            for (std::size_t j = 0; j < part.grid.ny(); ++j) {
                for (std::size_t i = 0; i < part.grid.nx(); ++i) {
                    const float a = got.values[part.grid.index(i, j, k)];
                    const float b = want.values[whole.grid.index(i, j, at.firstLayer + k)];
                    differ += (a == b || (std::isnan(a) && std::isnan(b))) ? 0 : 1;
                }
            }
        }
        EXPECT_EQ(differ, 0u) << "member " << at.firstMember + m;
    }
}

}  // namespace

TEST(EnsemblePart, SlabsOfOneFileWithMembersEqualTheWholeRead) {
    test::TempDir dir;
    const std::string path = dir.file("demo.nc");
    data::writeNetcdf(data::makeDemoEnsemble({.members = 5, .nx = 12, .ny = 9, .nz = 7}).ensemble,
                      path);
    const data::DataSelection selection{.paths = {path}};
    const data::EnsembleDescription description = data::describeEnsemble(selection);
    const data::Ensemble whole = data::openEnsemble(selection);
    for (const data::EnsemblePart& at :
         {data::EnsemblePart{0, 5, 0, 7}, data::EnsemblePart{1, 3, 2, 3},
          data::EnsemblePart{4, 1, 5, 2}}) {
        SCOPED_TRACE(testing::Message() << "members " << at.firstMember << "+" << at.memberCount
                                        << " layers " << at.firstLayer << "+" << at.layerCount);
        expectPartOfWhole(data::openEnsemblePart(selection, description, at), whole, at);
    }
}

TEST(EnsemblePart, SlabsAcrossFilesAndOfADerivedStaggeredVariable) {
    // Two files of two members each (member dimension "Time"), wind speed from WRF's U
    // (staggered along x) and V (staggered along y), 4 layers: a part that spans both files.
    test::TempDir dir;
    std::vector<std::string> paths;
    for (int f = 0; f < 2; ++f) {
        paths.push_back(dir.file("wrf_" + std::to_string(f) + ".nc"));
        test::NcTestFile file(paths.back());
        const int t = file.dim("Time", 2);
        const int z = file.dim("bottom_top", 4);
        const int y = file.dim("south_north", 3);
        const int ys = file.dim("south_north_stag", 4);
        const int x = file.dim("west_east", 4);
        const int xs = file.dim("west_east_stag", 5);
        const int u = file.variable("U", NC_FLOAT, {t, z, y, xs});
        const int v = file.variable("V", NC_FLOAT, {t, z, ys, x});
        file.write(u, std::size_t{2} * 4 * 3 * 5,
                   [&](std::size_t n) { return static_cast<double>(n % 7 + f); });
        file.write(v, std::size_t{2} * 4 * 4 * 4,
                   [](std::size_t n) { return static_cast<double>(n % 5); });
    }
    const data::DataSelection selection{
        .paths = paths, .variable = "wind_speed", .memberDimension = "Time"};
    const data::EnsembleDescription description = data::describeEnsemble(selection);
    ASSERT_EQ(description.members, 4u);
    const data::Ensemble whole = data::openEnsemble(selection);
    const data::EnsemblePart at{1, 2, 1, 3};
    expectPartOfWhole(data::openEnsemblePart(selection, description, at), whole, at);
}

TEST(EnsemblePart, PartsOutsideTheDataAreRefusedNamingTheVariableAndFile) {
    test::TempDir dir;
    const std::string path = dir.file("demo.nc");
    data::writeNetcdf(data::makeDemoEnsemble({.members = 3, .nx = 6, .ny = 5, .nz = 4}).ensemble,
                      path);
    const data::DataSelection selection{.paths = {path}};
    const data::EnsembleDescription description = data::describeEnsemble(selection);
    for (const data::EnsemblePart& at :
         {data::EnsemblePart{0, 4, 0, 4}, data::EnsemblePart{3, 1, 0, 4},
          data::EnsemblePart{0, 0, 0, 4}, data::EnsemblePart{0, 3, 3, 2},
          data::EnsemblePart{0, 3, 1, 1}, data::EnsemblePart{0, 3, 4, 2}}) {
        try {
            (void)data::openEnsemblePart(selection, description, at);
            ADD_FAILURE() << "part " << at.firstMember << "+" << at.memberCount << ", "
                          << at.firstLayer << "+" << at.layerCount << " was read";
        } catch (const data::Error& e) {
            EXPECT_EQ(e.kind(), data::ErrorKind::InvalidArgument);
            const std::string message = e.what();
            EXPECT_NE(message.find("'" + description.variable + "'"), std::string::npos) << message;
            EXPECT_NE(message.find(path), std::string::npos) << message;
        }
    }
}

TEST(EnsemblePart, AReaderWithoutSlabsSaysSoNamingTheFormat) {
    const data::Hdf5Reader reader;
    EXPECT_FALSE(reader.readsParts());
    try {
        (void)reader.readPart({.paths = {"/data/x.h5"}}, {}, {0, 1, 0, 2}, {}, {});
        FAIL() << "the HDF5 reader read a part";
    } catch (const data::Error& e) {
        EXPECT_EQ(e.kind(), data::ErrorKind::UnsupportedFormat);
        EXPECT_NE(std::string(e.what()).find("HDF5"), std::string::npos) << e.what();
    }
}

#include "data/hdf5_reader.h"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <stop_token>
#include <string>
#include <vector>

#include "data/error.h"
#include "reader_test_helpers.h"
#include "tests/support/temp_dir.h"

using namespace ensil::data;

namespace {

constexpr std::size_t kNx = 6, kNy = 5, kNz = 4;

// Every value tells where it belongs, so a transposed or shifted read cannot pass.
double field(std::size_t m, std::size_t x, std::size_t y, std::size_t z) {
    return static_cast<double>(1000 * m + x + 10 * y + 100 * z);
}

template <typename T>
std::vector<T> memberValues(std::size_t m, std::size_t nx = kNx, std::size_t ny = kNy,
                            std::size_t nz = kNz) {
    std::vector<T> values;
    for (std::size_t z = 0; z < nz; ++z) {
        for (std::size_t y = 0; y < ny; ++y) {
            for (std::size_t x = 0; x < nx; ++x)
                values.push_back(static_cast<T>(field(m, x, y, z)));
        }
    }
    return values;
}

// Writes HDF5 files with the C API, the way other tools would.
class H5Writer {
public:
    explicit H5Writer(const std::string& path)
        : m_file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)) {
        EXPECT_GE(m_file, 0) << path;
    }
    H5Writer(const H5Writer&) = delete;
    H5Writer& operator=(const H5Writer&) = delete;
    ~H5Writer() { H5Fclose(m_file); }

    void group(const std::string& path) {
        H5Gclose(H5Gcreate2(m_file, path.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    }
    template <typename T>
    void dataset(const std::string& path, const std::vector<hsize_t>& dims,
                 const std::vector<T>& values, hid_t type) {
        const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
        const hid_t set =
            H5Dcreate2(m_file, path.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        ASSERT_GE(set, 0) << path;
        ASSERT_GE(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0) << path;
        H5Dclose(set);
        H5Sclose(space);
    }
    void text(const std::string& object, const char* name, const std::string& value) {
        const hid_t type = H5Tcopy(H5T_C_S1);
        H5Tset_size(type, value.size());
        write(object, name, type, 1, value.c_str());
        H5Tclose(type);
    }
    template <typename T>
    void numbers(const std::string& object, const char* name, const std::vector<T>& values,
                 hid_t type) {
        write(object, name, type, values.size(), values.data());
    }
    // A string attribute as h5py writes it: variable-length UTF-8.
    void utf8(const std::string& object, const char* name, const std::string& value) {
        const hid_t type = H5Tcopy(H5T_C_S1);
        H5Tset_size(type, H5T_VARIABLE);
        H5Tset_cset(type, H5T_CSET_UTF8);
        const char* text = value.c_str();
        write(object, name, type, 1, &text);
        H5Tclose(type);
    }

private:
    void write(const std::string& object, const char* name, hid_t type, hsize_t count,
               const void* data) {
        const hid_t target = H5Oopen(m_file, object.c_str(), H5P_DEFAULT);
        const hid_t space =
            count == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr);
        const hid_t attr = H5Acreate2(target, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
        EXPECT_GE(H5Awrite(attr, type, data), 0) << object << " " << name;
        H5Aclose(attr);
        H5Sclose(space);
        H5Oclose(target);
    }
    hid_t m_file;
};

const std::vector<hsize_t> kMemberDims{kNz, kNy, kNx};

void writeFourDimensional(const std::string& path, std::size_t members = 3) {
    std::vector<float> values;
    for (std::size_t m = 0; m < members; ++m) {
        const auto member = memberValues<float>(m);
        values.insert(values.end(), member.begin(), member.end());
    }
    H5Writer file(path);
    file.dataset("/wind_speed", {members, kNz, kNy, kNx}, values, H5T_NATIVE_FLOAT);
    file.text("/wind_speed", "units", "m s-1");
    file.text("/wind_speed", "long_name", "Wind speed");
}

void expectMemberValues(const Ensemble& e, std::size_t member, std::size_t fieldIndex) {
    ASSERT_EQ(e.grid.nx(), kNx);
    ASSERT_EQ(e.grid.ny(), kNy);
    ASSERT_EQ(e.grid.nz(), kNz);
    const ensil::data::FieldValues& values = e.members.at(member).values;
    ASSERT_EQ(values.size(), kNx * kNy * kNz);
    for (std::size_t z = 0; z < kNz; ++z) {
        for (std::size_t y = 0; y < kNy; ++y) {
            for (std::size_t x = 0; x < kNx; ++x) {
                ASSERT_EQ(values[e.grid.index(x, y, z)],
                          static_cast<float>(field(fieldIndex, x, y, z)))
                    << "member " << member << " at x=" << x << " y=" << y << " z=" << z;
            }
        }
    }
}

}  // namespace

using ensil::test::contains;
using ensil::test::errorFrom;
using ensil::test::selection;

TEST(Hdf5Reader, FourDimensionalDatasetGivesOneMemberPerIndex) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("four.h5");
    writeFourDimensional(path);
    const Ensemble e = Hdf5Reader().read(selection({path}), {}, {});
    ASSERT_EQ(e.memberCount(), 3u);
    for (std::size_t m = 0; m < 3; ++m) expectMemberValues(e, m, m);
    EXPECT_EQ(e.members[0].name, "member 1");
    EXPECT_EQ(e.members[2].name, "member 3");
    EXPECT_EQ(e.variable, "wind_speed");
    EXPECT_EQ(e.units, "m s-1");
    EXPECT_EQ(e.longName, "Wind speed");
    EXPECT_EQ(e.memberDimension, "member");
    EXPECT_EQ(e.source, path);
    EXPECT_EQ(e.grid.x().values, (std::vector<double>{0, 1, 2, 3, 4, 5}));  // indices
    EXPECT_EQ(e.grid.z().values, (std::vector<double>{0, 1, 2, 3}));

    const EnsembleDescription d = Hdf5Reader().describe(selection({path}));
    EXPECT_EQ(d.format, "HDF5");
    EXPECT_EQ(d.variable, "/wind_speed");
    EXPECT_EQ(d.members, 3u);
    EXPECT_EQ(d.memberNames, (std::vector<std::string>{"member 1", "member 2", "member 3"}));
    EXPECT_EQ(d.units, "m s-1");
    EXPECT_EQ(d.bytes(), 3 * kNx * kNy * kNz * sizeof(float));
}

TEST(Hdf5Reader, GroupOfInt16DatasetsGivesMembersInNameOrder) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("group.h5");
    {
        H5Writer file(path);
        file.group("/members");
        // Created out of order: members follow the names, not the creation order.
        file.dataset("/members/run_c", kMemberDims, memberValues<short>(2), H5T_NATIVE_SHORT);
        file.dataset("/members/run_a", kMemberDims, memberValues<short>(0), H5T_NATIVE_SHORT);
        file.dataset("/members/run_b", kMemberDims, memberValues<short>(1), H5T_NATIVE_SHORT);
        file.text("/members", "units", "K");
    }
    const Ensemble e = Hdf5Reader().read(selection({path}, "/members"), {}, {});
    ASSERT_EQ(e.memberCount(), 3u);
    EXPECT_EQ(e.members[0].name, "run_a");
    EXPECT_EQ(e.members[1].name, "run_b");
    EXPECT_EQ(e.members[2].name, "run_c");
    for (std::size_t m = 0; m < 3; ++m) expectMemberValues(e, m, m);
    EXPECT_EQ(e.variable, "members");
    EXPECT_EQ(e.units, "K");
    EXPECT_EQ(e.memberDimension, "/members");
}

TEST(Hdf5Reader, OneDoubleFilePerMemberNamesMembersAfterFiles) {
    ensil::test::TempDir dir;
    std::vector<std::string> paths;
    for (std::size_t m = 0; m < 3; ++m) {
        paths.push_back(dir.file("run_0" + std::to_string(m + 1) + ".h5"));
        H5Writer file(paths.back());
        file.dataset("/temperature", kMemberDims, memberValues<double>(m), H5T_NATIVE_DOUBLE);
    }
    const Ensemble e = Hdf5Reader().read(selection(paths), {}, {});
    ASSERT_EQ(e.memberCount(), 3u);
    EXPECT_EQ(e.members[0].name, "run_01");
    EXPECT_EQ(e.members[2].name, "run_03");
    for (std::size_t m = 0; m < 3; ++m) expectMemberValues(e, m, m);
    EXPECT_EQ(e.variable, "temperature");
    EXPECT_EQ(e.memberDimension, "");
    EXPECT_EQ(e.source, "3 files in " + dir.path().string());
}

TEST(Hdf5Reader, EmptyVariablePrefersFourDimensionalThenGroupThenSingleDataset) {
    ensil::test::TempDir dir;
    const std::vector<float> flat(kNx * kNy, 1.0f);
    const auto member = memberValues<float>(0);
    {
        H5Writer file(dir.file("all.h5"));
        file.dataset("/a_t2m", {kNy, kNx}, flat, H5T_NATIVE_FLOAT);
        file.group("/b_members");
        file.dataset("/b_members/x", kMemberDims, member, H5T_NATIVE_FLOAT);
        file.dataset("/b_members/y", kMemberDims, member, H5T_NATIVE_FLOAT);
        std::vector<float> four(member);
        four.insert(four.end(), member.begin(), member.end());
        file.dataset("/c_volume", {2, kNz, kNy, kNx}, four, H5T_NATIVE_FLOAT);
    }
    {
        H5Writer file(dir.file("group.h5"));
        file.dataset("/a_t2m", {kNy, kNx}, flat, H5T_NATIVE_FLOAT);
        file.group("/b_members");
        file.dataset("/b_members/x", kMemberDims, member, H5T_NATIVE_FLOAT);
        file.dataset("/b_members/y", kMemberDims, member, H5T_NATIVE_FLOAT);
    }
    {
        H5Writer file(dir.file("single.h5"));
        file.dataset("/a_t2m", {kNy, kNx}, flat, H5T_NATIVE_FLOAT);
        file.dataset("/only", kMemberDims, member, H5T_NATIVE_FLOAT);
    }
    const Hdf5Reader reader;
    EXPECT_EQ(reader.describe(selection({dir.file("all.h5")})).variable, "/c_volume");
    EXPECT_EQ(reader.describe(selection({dir.file("group.h5")})).variable, "/b_members");
    const EnsembleDescription single = reader.describe(selection({dir.file("single.h5")}));
    EXPECT_EQ(single.variable, "/only");
    EXPECT_EQ(single.memberNames, std::vector<std::string>{"only"});
    const Ensemble e = reader.read(selection({dir.file("single.h5")}), {}, {});
    ASSERT_EQ(e.memberCount(), 1u);
    expectMemberValues(e, 0, 0);
}

// Files written by h5py: plain datasets, no dimension scales, no _NCProperties, the members in
// a group one or more levels down. netCDF-C opens such files too (it opens any HDF5 file), so
// the NetCDF reader once claimed them and refused them for holding no variables.
TEST(Hdf5Reader, H5pyMemberGroupsInSubgroupsOpenThroughTheHdf5Reader) {
    ensil::test::TempDir dir;
    const std::string ensemble = dir.file("h5py_ensemble.h5");
    {
        H5Writer file(ensemble);
        file.group("/ensemble");
        for (std::size_t m = 0; m < 3; ++m) {
            file.dataset("/ensemble/member_0" + std::to_string(m), kMemberDims,
                         memberValues<double>(m), H5T_NATIVE_DOUBLE);
        }
        file.utf8("/ensemble", "units", "K");
        file.utf8("/", "title", "written the way h5py writes");
    }
    const std::string deep = dir.file("h5py_deep.h5");
    {
        H5Writer file(deep);
        file.group("/data");
        file.group("/data/t");
        file.dataset("/data/lat", {kNy}, std::vector<double>{50, 51, 52, 53, 54},
                     H5T_NATIVE_DOUBLE);
        // Eleven members: m10 comes after m9, not after m1.
        for (std::size_t m = 0; m < 11; ++m) {
            file.dataset("/data/t/m" + std::to_string(m), kMemberDims, memberValues<float>(m),
                         H5T_NATIVE_FLOAT);
        }
    }
    const DataSelection first = selection({ensemble});
    EXPECT_EQ(readerFor(first).name(), "HDF5");
    EnsembleDescription d;
    const Ensemble e = openEnsemble(first, {}, {}, &d);
    EXPECT_EQ(d.format, "HDF5");
    EXPECT_EQ(d.variable, "/ensemble");
    EXPECT_EQ(d.memberNames, (std::vector<std::string>{"member_00", "member_01", "member_02"}));
    EXPECT_EQ(e.units, "K");
    ASSERT_EQ(e.memberCount(), 3u);
    for (std::size_t m = 0; m < 3; ++m) expectMemberValues(e, m, m);

    const DataSelection second = selection({deep});
    EXPECT_EQ(readerFor(second).name(), "HDF5");
    const Ensemble t = openEnsemble(second, {}, {}, &d);
    EXPECT_EQ(d.variable, "/data/t");
    ASSERT_EQ(t.memberCount(), 11u);
    for (std::size_t m = 0; m < 11; ++m) {
        EXPECT_EQ(t.members[m].name, "m" + std::to_string(m));
        expectMemberValues(t, m, m);
    }
    // Named with --var, with or without the leading slash.
    EXPECT_EQ(describeEnsemble(selection({deep}, "data/t")).members, 11u);
}

TEST(Hdf5Reader, SeveralMemberGroupsAreSaidAndVarChoosesAmongThem) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("two_variables.h5");
    {
        H5Writer file(path);
        file.group("/ensemble");
        file.group("/ensemble/u");
        file.group("/ensemble/t");
        for (std::size_t m = 0; m < 2; ++m) {
            file.dataset("/ensemble/u/m" + std::to_string(m), kMemberDims,
                         memberValues<float>(m + 5), H5T_NATIVE_FLOAT);
            file.dataset("/ensemble/t/m" + std::to_string(m), kMemberDims, memberValues<float>(m),
                         H5T_NATIVE_FLOAT);
        }
    }
    // The first in name order, and the reason says which others there are and how to choose.
    const EnsembleDescription d = describeEnsemble(selection({path}));
    EXPECT_EQ(d.variable, "/ensemble/t");
    EXPECT_TRUE(d.memberDimensionReason.find("'/ensemble/t', '/ensemble/u'") != std::string::npos)
        << d.memberDimensionReason;
    EXPECT_TRUE(d.memberDimensionReason.find("--var") != std::string::npos)
        << d.memberDimensionReason;
    const Ensemble u = openEnsemble(selection({path}, "/ensemble/u"));
    ASSERT_EQ(u.memberCount(), 2u);
    for (std::size_t m = 0; m < 2; ++m) expectMemberValues(u, m, m + 5);
}

TEST(Hdf5Reader, FilesWithDimensionScalesAndTheirDataInASubgroupGoToTheHdf5Reader) {
    // Dimension scales in the root group, the members in /ensemble: netCDF-C sees only the
    // root's scales, and the NetCDF reader used to claim the file and say it held no field.
    // Written through netCDF-4's groups; once as netCDF writes it, once without _NCProperties
    // (as a writer of dimension scales that is not netCDF, h5py's dims API, leaves it).
    ensil::test::TempDir dir;
    for (const bool ncProperties : {true, false}) {
        const std::string path =
            dir.file(ncProperties ? "groups_netcdf4.nc" : "groups_dimension_scales.h5");
        int nc = -1;
        ASSERT_EQ(nc_create(path.c_str(), NC_NETCDF4, &nc), NC_NOERR);
        int dims[3] = {};
        nc_def_dim(nc, "z", kNz, &dims[0]);
        nc_def_dim(nc, "y", kNy, &dims[1]);
        nc_def_dim(nc, "x", kNx, &dims[2]);
        int group = -1;
        ASSERT_EQ(nc_def_grp(nc, "ensemble", &group), NC_NOERR);
        for (std::size_t m = 0; m < 3; ++m) {
            int var = -1;
            const std::string name = "member_0" + std::to_string(m);
            ASSERT_EQ(nc_def_var(group, name.c_str(), NC_FLOAT, 3, dims, &var), NC_NOERR);
            ASSERT_EQ(nc_put_var_float(group, var, memberValues<float>(m).data()), NC_NOERR);
        }
        ASSERT_EQ(nc_close(nc), NC_NOERR);
        if (!ncProperties) {
            const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
            ASSERT_GE(file, 0);
            EXPECT_GE(H5Adelete(file, "_NCProperties"), 0);
            H5Fclose(file);
        }
        SCOPED_TRACE(path);
        const DataSelection s = selection({path});
        EXPECT_EQ(readerFor(s).name(), "HDF5");
        EnsembleDescription d;
        const Ensemble e = openEnsemble(s, {}, {}, &d);
        EXPECT_EQ(d.variable, "/ensemble");
        ASSERT_EQ(e.memberCount(), 3u);
        for (std::size_t m = 0; m < 3; ++m) expectMemberValues(e, m, m);
    }
}

TEST(Hdf5Reader, RealNetcdf4FilesStillGoToTheNetcdfReader) {
    for (const char* name :
         {"era5_eda_members.nc", "glosea4_surface_temperature_ensemble.nc", "uk_hires.nc"}) {
        const std::string path = std::string(ENSIL_SHARED_DATA_DIR "/") + name;
        EXPECT_EQ(readerFor(selection({path})).name(), "NetCDF") << name;
    }
    // And a netCDF-4 file without _NCProperties (written before netCDF 4.4.1): its variables
    // have dimension scales.
    ensil::test::TempDir dir;
    const std::string old = dir.file("old_netcdf4.nc");
    {
        int nc = -1;
        ASSERT_EQ(nc_create(old.c_str(), NC_NETCDF4, &nc), NC_NOERR);
        int dims[3] = {};
        nc_def_dim(nc, "z", kNz, &dims[0]);
        nc_def_dim(nc, "y", kNy, &dims[1]);
        nc_def_dim(nc, "x", kNx, &dims[2]);
        int var = -1;
        nc_def_var(nc, "t", NC_FLOAT, 3, dims, &var);
        ASSERT_EQ(nc_close(nc), NC_NOERR);
        const hid_t file = H5Fopen(old.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
        ASSERT_GE(file, 0);
        EXPECT_GE(H5Adelete(file, "_NCProperties"), 0);
        H5Fclose(file);
    }
    EXPECT_EQ(readerFor(selection({old})).name(), "NetCDF");
}

TEST(Hdf5Reader, OriginAndSpacingAttributesGiveUniformAxes) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("axes.h5");
    {
        H5Writer file(path);
        file.dataset("/t", kMemberDims, memberValues<float>(0), H5T_NATIVE_FLOAT);
        file.numbers("/t", "origin", std::vector<double>{10.0, -20.0, 1000.0}, H5T_NATIVE_DOUBLE);
        file.numbers("/t", "spacing", std::vector<double>{0.5, 2.0, -100.0}, H5T_NATIVE_DOUBLE);
    }
    const Ensemble e = Hdf5Reader().read(selection({path}), {}, {});
    EXPECT_EQ(e.grid.x().values, (std::vector<double>{10.0, 10.5, 11.0, 11.5, 12.0, 12.5}));
    EXPECT_EQ(e.grid.y().values, (std::vector<double>{-20.0, -18.0, -16.0, -14.0, -12.0}));
    EXPECT_EQ(e.grid.z().values, (std::vector<double>{1000.0, 900.0, 800.0, 700.0}));
    EXPECT_EQ(e.grid.x().name, "x");
    EXPECT_EQ(e.grid.z().name, "z");
}

TEST(Hdf5Reader, FillValueAndMissingValueBecomeNaN) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("missing.h5");
    auto shorts = memberValues<short>(0);
    auto doubles = memberValues<double>(1);
    shorts[7] = -999;
    doubles[0] = 1e20;
    doubles[42] = 1e20;
    {
        H5Writer file(path);
        file.dataset("/counts", kMemberDims, shorts, H5T_NATIVE_SHORT);
        file.numbers("/counts", "_FillValue", std::vector<short>{-999}, H5T_NATIVE_SHORT);
        file.dataset("/heights", kMemberDims, doubles, H5T_NATIVE_DOUBLE);
        file.numbers("/heights", "missing_value", std::vector<double>{1e20}, H5T_NATIVE_DOUBLE);
    }
    const Ensemble counts = Hdf5Reader().read(selection({path}, "counts"), {}, {});
    const Ensemble heights = Hdf5Reader().read(selection({path}, "heights"), {}, {});
    for (std::size_t i = 0; i < shorts.size(); ++i) {
        if (i == 7) {
            EXPECT_TRUE(std::isnan(counts.members[0].values[i]));
        } else {
            ASSERT_EQ(counts.members[0].values[i], static_cast<float>(shorts[i])) << i;
        }
        if (i == 0 || i == 42) {
            EXPECT_TRUE(std::isnan(heights.members[0].values[i])) << i;
        } else {
            ASSERT_EQ(heights.members[0].values[i], static_cast<float>(doubles[i])) << i;
        }
    }
}

TEST(Hdf5Reader, DescribeExplainsWhyDatasetsAreUnusable) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("mixed.h5");
    {
        H5Writer file(path);
        file.dataset("/t2m", {kNy, kNx}, std::vector<float>(kNx * kNy, 1.0f), H5T_NATIVE_FLOAT);
        const hid_t text = H5Tcopy(H5T_C_S1);
        H5Tset_size(text, 4);
        file.dataset("/labels", {2}, std::vector<char>{'a', 'b', 'c', '\0', 'd', 'e', 'f', '\0'},
                     text);
        H5Tclose(text);
        file.dataset("/wind", {2, kNz, kNy, kNx}, std::vector<float>(2 * kNx * kNy * kNz, 3.0f),
                     H5T_NATIVE_FLOAT);
        file.text("/wind", "units", "m s-1");
    }
    const EnsembleDescription d = Hdf5Reader().describe(selection({path}));
    ASSERT_EQ(d.variables.size(), 3u);
    std::map<std::string, VariableInfo> byName;
    for (const VariableInfo& v : d.variables) byName[v.name] = v;
    EXPECT_FALSE(byName["/t2m"].usable);
    EXPECT_EQ(byName["/t2m"].whyNotUsable,
              "dataset '/t2m' has rank 2: ensil needs (member, z, y, x) or one (z, y, x) dataset "
              "per member");
    EXPECT_FALSE(byName["/labels"].usable);
    EXPECT_NE(byName["/labels"].whyNotUsable.find("strings"), std::string::npos);
    EXPECT_TRUE(byName["/wind"].usable);
    EXPECT_EQ(byName["/wind"].units, "m s-1");
    EXPECT_EQ(byName["/wind"].shape, (std::vector<std::size_t>{2, kNz, kNy, kNx}));
    EXPECT_EQ(d.variable, "/wind");
}

TEST(Hdf5Reader, WrongVariableNameListsTheUsableOnes) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("four.h5");
    writeFourDimensional(path);
    const Error e = errorFrom<Hdf5Reader>(selection({path}, "windspeed"));
    EXPECT_EQ(e.kind(), ErrorKind::VariableNotFound);
    EXPECT_TRUE(contains(e, "'/windspeed'")) << e.what();
    EXPECT_TRUE(contains(e, "'/wind_speed'")) << e.what();
    EXPECT_TRUE(contains(e, path)) << e.what();
}

TEST(Hdf5Reader, FilesOnDifferentGridsAreRefusedNamingBoth) {
    ensil::test::TempDir dir;
    const std::string a = dir.file("a.h5");
    const std::string b = dir.file("b.h5");
    {
        H5Writer file(a);
        file.dataset("/t", kMemberDims, memberValues<float>(0), H5T_NATIVE_FLOAT);
    }
    {
        H5Writer file(b);
        file.dataset("/t", {kNz, kNy, kNx + 1}, memberValues<float>(0, kNx + 1), H5T_NATIVE_FLOAT);
    }
    const Error e = errorFrom<Hdf5Reader>(selection({a, b}));
    EXPECT_EQ(e.kind(), ErrorKind::GridMismatch);
    EXPECT_TRUE(contains(e, a) && contains(e, b)) << e.what();
    EXPECT_TRUE(contains(e, "6 x 5 x 4") && contains(e, "7 x 5 x 4")) << e.what();
}

TEST(Hdf5Reader, TwoDimensionalDataIsRefused) {
    ensil::test::TempDir dir;
    const std::string flat = dir.file("flat.h5");
    const std::string thin = dir.file("thin.h5");
    {
        H5Writer file(flat);
        file.dataset("/t2m", {kNy, kNx}, std::vector<float>(kNx * kNy, 1.0f), H5T_NATIVE_FLOAT);
    }
    {
        H5Writer file(thin);
        file.dataset("/layer", {1, kNy, kNx}, std::vector<float>(kNx * kNy, 1.0f),
                     H5T_NATIVE_FLOAT);
    }
    const Error rank2 = errorFrom<Hdf5Reader>(selection({flat}));
    EXPECT_EQ(rank2.kind(), ErrorKind::NotThreeDimensional);
    EXPECT_TRUE(contains(rank2, "rank 2")) << rank2.what();
    const Error oneLevel = errorFrom<Hdf5Reader>(selection({thin}, "layer"));
    EXPECT_EQ(oneLevel.kind(), ErrorKind::NotThreeDimensional);
    EXPECT_TRUE(contains(oneLevel, "6 x 5 x 1")) << oneLevel.what();
}

TEST(Hdf5Reader, TruncatedFileIsCorruptAndPrintsNothing) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("cut.h5");
    writeFourDimensional(path, 8);
    std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
    ASSERT_TRUE(Hdf5Reader().recognizes(path));
    testing::internal::CaptureStderr();
    const Error e = errorFrom<Hdf5Reader>(selection({path}));
    const std::string printed = testing::internal::GetCapturedStderr();
    EXPECT_EQ(e.kind(), ErrorKind::CorruptFile);
    EXPECT_TRUE(contains(e, path)) << e.what();
    EXPECT_EQ(printed, "");
}

TEST(Hdf5Reader, FileThatIsNotHdf5IsRefused) {
    ensil::test::TempDir dir;
    const std::string text = dir.file("notes.h5");
    std::ofstream(text) << "time,temperature\n0,12.5\n";
    const std::string real = dir.file("real.h5");
    writeFourDimensional(real);
    EXPECT_FALSE(Hdf5Reader().recognizes(text));
    EXPECT_TRUE(Hdf5Reader().recognizes(real));
    const Error e = errorFrom<Hdf5Reader>(selection({text}));
    EXPECT_EQ(e.kind(), ErrorKind::UnsupportedFormat);
    EXPECT_TRUE(contains(e, text)) << e.what();
    EXPECT_EQ(errorFrom<Hdf5Reader>(selection({dir.file("absent.h5")})).kind(),
              ErrorKind::FileNotFound);
}

TEST(Hdf5Reader, ProgressRisesToOneAndAStopBetweenMembersCancels) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("four.h5");
    writeFourDimensional(path, 4);
    std::vector<double> seen;
    (void)Hdf5Reader().read(selection({path}), {}, [&](double f) { seen.push_back(f); });
    ASSERT_FALSE(seen.empty());
    EXPECT_TRUE(std::ranges::is_sorted(seen));
    EXPECT_GE(seen.front(), 0.0);
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);

    std::stop_source stop;
    std::vector<double> beforeCancel;
    const auto cancelAfterFirst = [&](double f) {
        beforeCancel.push_back(f);
        if (f > 0.0) stop.request_stop();
    };
    EXPECT_THROW((void)Hdf5Reader().read(selection({path}), stop.get_token(), cancelAfterFirst),
                 Cancelled);
    EXPECT_EQ(beforeCancel, (std::vector<double>{0.0, 0.25}));
}

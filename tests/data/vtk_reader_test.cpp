#include "data/vtk_reader.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkRectilinearGrid.h>
#include <vtkRectilinearGridWriter.h>
#include <vtkShortArray.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredPointsWriter.h>
#include <vtkXMLImageDataWriter.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stop_token>
#include <string>
#include <vector>

#include "data/error.h"
#include "reader_test_helpers.h"
#include "tests/support/temp_dir.h"

using namespace ensil::data;

namespace {

constexpr int kGridX = 6, kGridY = 5, kGridZ = 4;

// Every value tells where it belongs, so a transposed or shifted read cannot pass.
double field(int m, int x, int y, int z) { return 1000.0 * m + x + 10.0 * y + 100.0 * z; }

template <typename Array>
void addScalars(vtkDataSet& data, const char* name, int member, const std::array<int, 3>& dims) {
    vtkNew<Array> array;
    array->SetName(name);
    array->SetNumberOfTuples(static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2]);
    vtkIdType i = 0;
    for (int z = 0; z < dims[2]; ++z) {
        for (int y = 0; y < dims[1]; ++y) {
            for (int x = 0; x < dims[0]; ++x) array->SetValue(i++, field(member, x, y, z));
        }
    }
    data.GetPointData()->AddArray(array);
}

void addVectors(vtkDataSet& data, const char* name) {
    vtkNew<vtkFloatArray> array;
    array->SetName(name);
    array->SetNumberOfComponents(3);
    array->SetNumberOfTuples(data.GetNumberOfPoints());
    array->Fill(1.0);
    data.GetPointData()->AddArray(array);
}

vtkSmartPointer<vtkImageData> image(std::array<int, 3> dims = {kGridX, kGridY, kGridZ},
                                    std::array<double, 3> origin = {0, 0, 0},
                                    std::array<double, 3> spacing = {1, 1, 1}) {
    auto img = vtkSmartPointer<vtkImageData>::New();
    img->SetDimensions(dims.data());
    img->SetOrigin(origin.data());
    img->SetSpacing(spacing.data());
    return img;
}

void writeXml(vtkImageData* img, const std::string& path) {
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(img);
    writer->SetFileName(path.c_str());
    ASSERT_EQ(writer->Write(), 1) << path;
}

void writeLegacy(vtkImageData* img, const std::string& path, bool binary) {
    vtkNew<vtkStructuredPointsWriter> writer;
    writer->SetInputData(img);
    writer->SetFileName(path.c_str());
    if (binary) writer->SetFileTypeToBinary();
    ASSERT_EQ(writer->Write(), 1) << path;
}

void expectMemberValues(const Ensemble& e, std::size_t member, int fieldIndex,
                        std::array<int, 3> dims = {kGridX, kGridY, kGridZ}) {
    ASSERT_EQ(e.grid.nx(), static_cast<std::size_t>(dims[0]));
    ASSERT_EQ(e.grid.ny(), static_cast<std::size_t>(dims[1]));
    ASSERT_EQ(e.grid.nz(), static_cast<std::size_t>(dims[2]));
    const ensil::data::FieldValues& values = e.members.at(member).values;
    ASSERT_EQ(values.size(), e.grid.pointCount());
    for (int z = 0; z < dims[2]; ++z) {
        for (int y = 0; y < dims[1]; ++y) {
            for (int x = 0; x < dims[0]; ++x) {
                const auto at =
                    e.grid.index(static_cast<std::size_t>(x), static_cast<std::size_t>(y),
                                 static_cast<std::size_t>(z));
                ASSERT_EQ(values[at], static_cast<float>(field(fieldIndex, x, y, z)))
                    << "member " << member << " at x=" << x << " y=" << y << " z=" << z;
            }
        }
    }
}

}  // namespace

using ensil::test::contains;
using ensil::test::errorFrom;
using ensil::test::selection;

TEST(VtkReader, LegacyStructuredPointsReadsEveryValueInPlace) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("volume.vtk");
    auto img = image({kGridX, kGridY, kGridZ}, {1.0, -2.0, 3.0}, {0.5, 1.0, 2.0});
    addScalars<vtkFloatArray>(*img, "f", 0, {kGridX, kGridY, kGridZ});
    writeLegacy(img, path, true);

    const Ensemble e = VtkReader().read(selection({path}), {}, {});
    ASSERT_EQ(e.memberCount(), 1u);
    expectMemberValues(e, 0, 0);
    EXPECT_EQ(e.members[0].name, "volume");
    EXPECT_EQ(e.variable, "f");
    EXPECT_EQ(e.source, path);
    EXPECT_EQ(e.memberDimension, "");
    EXPECT_EQ(e.grid.x().values, (std::vector<double>{1.0, 1.5, 2.0, 2.5, 3.0, 3.5}));
    EXPECT_EQ(e.grid.y().values, (std::vector<double>{-2.0, -1.0, 0.0, 1.0, 2.0}));
    EXPECT_EQ(e.grid.z().values, (std::vector<double>{3.0, 5.0, 7.0, 9.0}));
    EXPECT_EQ(e.grid.x().name, "x");
    EXPECT_EQ(e.grid.z().units, "");

    const EnsembleDescription d = VtkReader().describe(selection({path}));
    EXPECT_EQ(d.format, "VTK legacy");
    EXPECT_EQ(d.variable, "f");
    EXPECT_EQ(d.members, 1u);
    EXPECT_TRUE(d.grid.sameShapeAndCoordinates(e.grid));
}

TEST(VtkReader, LegacyRectilinearGridKeepsItsCoordinates) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("levels.vtk");
    const std::vector<double> xs{0, 1, 3, 7, 15, 31}, ys{-5, 0, 5, 10, 20}, zs{1000, 850, 500, 250};
    vtkNew<vtkRectilinearGrid> grid;
    grid->SetDimensions(kGridX, kGridY, kGridZ);
    const std::array<std::vector<double>, 3> axes{xs, ys, zs};
    std::array<vtkNew<vtkDoubleArray>, 3> coords;
    for (std::size_t a = 0; a < 3; ++a) {
        for (const double v : axes[a]) coords[a]->InsertNextValue(v);
    }
    grid->SetXCoordinates(coords[0]);
    grid->SetYCoordinates(coords[1]);
    grid->SetZCoordinates(coords[2]);
    addScalars<vtkDoubleArray>(*grid, "temperature", 2, {kGridX, kGridY, kGridZ});
    vtkNew<vtkRectilinearGridWriter> writer;
    writer->SetInputData(grid);
    writer->SetFileName(path.c_str());
    ASSERT_EQ(writer->Write(), 1);

    const Ensemble e = VtkReader().read(selection({path}), {}, {});
    expectMemberValues(e, 0, 2);
    EXPECT_EQ(e.grid.x().values, xs);
    EXPECT_EQ(e.grid.y().values, ys);
    EXPECT_EQ(e.grid.z().values, zs);
}

TEST(VtkReader, XmlImagesOfInt16MakeOneMemberPerFile) {
    ensil::test::TempDir dir;
    std::vector<std::string> paths;
    for (int m = 0; m < 3; ++m) {
        auto img = image();
        addScalars<vtkShortArray>(*img, "height", m, {kGridX, kGridY, kGridZ});
        paths.push_back(dir.file("member_" + std::to_string(m + 1) + ".vti"));
        writeXml(img, paths.back());
    }
    const Ensemble e = VtkReader().read(selection(paths), {}, {});
    ASSERT_EQ(e.memberCount(), 3u);
    for (std::size_t m = 0; m < 3; ++m) expectMemberValues(e, m, static_cast<int>(m));
    EXPECT_EQ(e.members[0].name, "member_1");
    EXPECT_EQ(e.members[2].name, "member_3");
    EXPECT_EQ(e.source, "3 files in " + dir.path().string());
    EXPECT_EQ(e.memberDimension, "");

    const EnsembleDescription d = VtkReader().describe(selection(paths));
    EXPECT_EQ(d.format, "VTK XML image");
    EXPECT_EQ(d.members, 3u);
    EXPECT_EQ(d.memberNames, (std::vector<std::string>{"member_1", "member_2", "member_3"}));
    EXPECT_EQ(d.variable, "height");
}

TEST(VtkReader, XmlExtentNotStartingAtZeroShiftsTheAxes) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("piece.vti");
    auto img = image();
    img->SetExtent(2, 2 + kGridX - 1, 0, kGridY - 1, 0, kGridZ - 1);
    img->SetOrigin(10.0, 0.0, 0.0);
    addScalars<vtkFloatArray>(*img, "f", 0, {kGridX, kGridY, kGridZ});
    writeXml(img, path);
    const Ensemble e = VtkReader().read(selection({path}), {}, {});
    expectMemberValues(e, 0, 0);
    EXPECT_DOUBLE_EQ(e.grid.x().front(), 12.0);
    EXPECT_DOUBLE_EQ(e.grid.x().back(), 17.0);
}

TEST(VtkReader, DefaultIsTheFirstScalarArrayAndOthersCanBeNamed) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("arrays.vti");
    auto img = image();
    addVectors(*img, "velocity");
    addScalars<vtkFloatArray>(*img, "pressure", 1, {kGridX, kGridY, kGridZ});
    addScalars<vtkDoubleArray>(*img, "density", 2, {kGridX, kGridY, kGridZ});
    writeXml(img, path);
    const Ensemble first = VtkReader().read(selection({path}), {}, {});
    EXPECT_EQ(first.variable, "pressure");
    expectMemberValues(first, 0, 1);
    const Ensemble named = VtkReader().read(selection({path}, "density"), {}, {});
    EXPECT_EQ(named.variable, "density");
    expectMemberValues(named, 0, 2);
}

TEST(VtkReader, MultiComponentArrayIsRefusedSuggestingAScalarOne) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("arrays.vti");
    auto img = image();
    addVectors(*img, "velocity");
    addScalars<vtkFloatArray>(*img, "pressure", 1, {kGridX, kGridY, kGridZ});
    writeXml(img, path);
    const Error e = errorFrom<VtkReader>(selection({path}, "velocity"));
    EXPECT_EQ(e.kind(), ErrorKind::InvalidArgument);
    EXPECT_TRUE(contains(e, "3 components")) << e.what();
    EXPECT_TRUE(contains(e, "'pressure'")) << e.what();
}

TEST(VtkReader, WrongArrayNameListsTheAvailableArrays) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("arrays.vti");
    auto img = image();
    addVectors(*img, "velocity");
    addScalars<vtkFloatArray>(*img, "pressure", 1, {kGridX, kGridY, kGridZ});
    writeXml(img, path);
    const Error e = errorFrom<VtkReader>(selection({path}, "temperature"));
    EXPECT_EQ(e.kind(), ErrorKind::VariableNotFound);
    EXPECT_TRUE(contains(e, "'temperature'")) << e.what();
    EXPECT_TRUE(contains(e, "'velocity' (3 components), 'pressure'")) << e.what();
    EXPECT_TRUE(contains(e, path)) << e.what();
}

class VtkLegacyArrays : public testing::TestWithParam<bool> {};

// The header scan must step over every array kind the writer emits, in both encodings.
TEST_P(VtkLegacyArrays, DescribeListsPointArraysInFileOrderAndReadsFieldArrays) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("many.vtk");
    auto img = image();
    vtkNew<vtkFloatArray> cells;
    cells->SetName("cell_only");
    cells->SetNumberOfTuples(img->GetNumberOfCells());
    cells->Fill(7.0);
    img->GetCellData()->AddArray(cells);
    addScalars<vtkShortArray>(*img, "s", 0, {kGridX, kGridY, kGridZ});
    img->GetPointData()->SetActiveScalars("s");
    addVectors(*img, "vel");
    addScalars<vtkFloatArray>(*img, "f", 1, {kGridX, kGridY, kGridZ});
    writeLegacy(img, path, GetParam());

    const EnsembleDescription d = VtkReader().describe(selection({path}));
    std::vector<std::string> names;
    for (const VariableInfo& v : d.variables) names.push_back(v.name);
    EXPECT_EQ(names, (std::vector<std::string>{"s", "vel", "f"}));
    ASSERT_EQ(d.variables.size(), 3u);
    EXPECT_TRUE(d.variables[0].usable);
    EXPECT_FALSE(d.variables[1].usable);
    EXPECT_NE(d.variables[1].whyNotUsable.find("3 components"), std::string::npos);
    EXPECT_EQ(d.variables[2].shape, (std::vector<std::size_t>{kGridZ, kGridY, kGridX}));
    EXPECT_EQ(d.variable, "s");

    expectMemberValues(VtkReader().read(selection({path}), {}, {}), 0, 0);
    expectMemberValues(VtkReader().read(selection({path}, "f"), {}, {}), 0, 1);
}

INSTANTIATE_TEST_SUITE_P(BinaryAndAscii, VtkLegacyArrays, testing::Bool(),
                         [](const testing::TestParamInfo<bool>& p) {
                             return p.param ? "Binary" : "Ascii";
                         });

// VTK 5.1+ writers may follow any array with a METADATA block (component names, INFORMATION keys
// with NAME/LOCATION and DATA lines), ended by an empty line: after SCALARS and VECTORS, after
// each array of a FIELD, and after the dataset's own field data. The scan once took METADATA in
// a FIELD for the next array's name and refused the file.
TEST(VtkReader, MetadataBlocksAfterArraysAreSkipped) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("metadata.vtk");
    std::ofstream(path) << "# vtk DataFile Version 5.1\n"
                           "arrays with metadata\n"
                           "ASCII\n"
                           "DATASET STRUCTURED_POINTS\n"
                           "FIELD FieldData 1\n"
                           "TIME 1 1 double\n"
                           "0.5\n"
                           "METADATA\n"
                           "INFORMATION 0\n"
                           "\n"
                           "DIMENSIONS 2 2 2\n"
                           "ORIGIN 0 0 0\n"
                           "SPACING 1 1 1\n"
                           "POINT_DATA 8\n"
                           "SCALARS s float 1\n"
                           "LOOKUP_TABLE default\n"
                           "0 1 2 3 4 5 6 7\n"
                           "METADATA\n"
                           "INFORMATION 0\n"
                           "\n"
                           "VECTORS vel float\n"
                           "0 0 1 0 0 1 0 0 1 0 0 1 0 0 1 0 0 1 0 0 1 0 0 1\n"
                           "METADATA\n"
                           "COMPONENT_NAMES\n"
                           "east\n"
                           "\n"
                           "up\n"
                           "INFORMATION 1\n"
                           "NAME L2_NORM_RANGE LOCATION vtkDataArray\n"
                           "DATA 2 1 1\n"
                           "\n"
                           "FIELD FieldData 2\n"
                           "f 1 8 float\n"
                           "10 11 12 13 14 15 16 17\n"
                           "METADATA\n"
                           "INFORMATION 2\n"
                           "NAME L2_NORM_RANGE LOCATION vtkDataArray\n"
                           "DATA 2 10 17\n"
                           "NAME COMPONENT_RANGE LOCATION vtkDataArray\n"
                           "DATA 2 10 17\n"
                           "\n"
                           "g 1 8 double\n"
                           "20 21 22 23 24 25 26 27\n"
                           "METADATA\n"
                           "INFORMATION 0\n"
                           "\n";
    const EnsembleDescription d = VtkReader().describe(selection({path}));
    std::vector<std::string> names;
    for (const VariableInfo& v : d.variables) names.push_back(v.name);
    EXPECT_EQ(names, (std::vector<std::string>{"s", "vel", "f", "g"}));
    EXPECT_EQ(d.variable, "s");
    for (const auto& [name, first] :
         {std::pair<std::string, float>{"s", 0.0F}, {"f", 10.0F}, {"g", 20.0F}}) {
        const Ensemble e = VtkReader().read(selection({path}, name), {}, {});
        ASSERT_EQ(e.members.at(0).values.size(), 8u) << name;
        for (std::size_t i = 0; i < 8; ++i) {
            EXPECT_EQ(e.members[0].values[i], first + static_cast<float>(i)) << name << " " << i;
        }
    }
}

// What VTK 9's own writer emits: arrays VTK has cached ranges for carry INFORMATION keys, named
// components COMPONENT_NAMES (an unnamed one an empty line), in both encodings.
TEST_P(VtkLegacyArrays, TheVtkWritersMetadataBlocksAreSkipped) {
    ensil::test::TempDir dir;
    const std::string path = dir.file("metadata.vtk");
    auto img = image();
    vtkNew<vtkDoubleArray> time;
    time->SetName("TIME");
    time->InsertNextValue(0.5);
    img->GetFieldData()->AddArray(time);
    addScalars<vtkFloatArray>(*img, "s", 0, {kGridX, kGridY, kGridZ});
    img->GetPointData()->SetActiveScalars("s");
    addVectors(*img, "vel");
    img->GetPointData()->SetActiveVectors("vel");
    addScalars<vtkDoubleArray>(*img, "f", 1, {kGridX, kGridY, kGridZ});
    addVectors(*img, "wind");
    img->GetPointData()->GetArray("wind")->SetComponentName(0, "east");
    addScalars<vtkShortArray>(*img, "h", 2, {kGridX, kGridY, kGridZ});
    img->GetPointData()->GetArray("h")->SetComponentName(0, "height");
    // Asking for a range caches it in the array's information, which the writer then writes.
    time->GetRange();
    for (int a = 0; a < img->GetPointData()->GetNumberOfArrays(); ++a) {
        img->GetPointData()->GetArray(a)->GetRange(-1);
        img->GetPointData()->GetArray(a)->GetRange(0);
    }
    writeLegacy(img, path, GetParam());
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_NE(text.find("METADATA"), std::string::npos) << "the writer wrote no metadata";
    ASSERT_NE(text.find("INFORMATION"), std::string::npos);
    ASSERT_NE(text.find("COMPONENT_NAMES"), std::string::npos);

    const EnsembleDescription d = VtkReader().describe(selection({path}));
    std::vector<std::string> names;
    for (const VariableInfo& v : d.variables) names.push_back(v.name);
    EXPECT_EQ(names, (std::vector<std::string>{"s", "vel", "f", "wind", "h"}));
    expectMemberValues(VtkReader().read(selection({path}), {}, {}), 0, 0);
    expectMemberValues(VtkReader().read(selection({path}, "f"), {}, {}), 0, 1);
    expectMemberValues(VtkReader().read(selection({path}, "h"), {}, {}), 0, 2);
}

TEST(VtkReader, FilesOnDifferentGridsAreRefusedNamingBoth) {
    ensil::test::TempDir dir;
    const std::string a = dir.file("a.vti"), b = dir.file("b.vti"), c = dir.file("c.vti");
    auto small = image();
    addScalars<vtkFloatArray>(*small, "f", 0, {kGridX, kGridY, kGridZ});
    writeXml(small, a);
    auto wider = image({kGridX + 1, kGridY, kGridZ});
    addScalars<vtkFloatArray>(*wider, "f", 0, {kGridX + 1, kGridY, kGridZ});
    writeXml(wider, b);
    auto stretched = image({kGridX, kGridY, kGridZ}, {0, 0, 0}, {2, 1, 1});
    addScalars<vtkFloatArray>(*stretched, "f", 0, {kGridX, kGridY, kGridZ});
    writeXml(stretched, c);

    const Error sizes = errorFrom<VtkReader>(selection({a, b}));
    EXPECT_EQ(sizes.kind(), ErrorKind::GridMismatch);
    EXPECT_TRUE(contains(sizes, a) && contains(sizes, b)) << sizes.what();
    EXPECT_TRUE(contains(sizes, "6 x 5 x 4") && contains(sizes, "7 x 5 x 4")) << sizes.what();
    const Error spacing = errorFrom<VtkReader>(selection({a, c}));
    EXPECT_EQ(spacing.kind(), ErrorKind::GridMismatch);
    EXPECT_TRUE(contains(spacing, a) && contains(spacing, c)) << spacing.what();
}

TEST(VtkReader, TwoDimensionalImageIsRefused) {
    ensil::test::TempDir dir;
    auto flat = image({kGridX, kGridY, 1});
    addScalars<vtkFloatArray>(*flat, "f", 0, {kGridX, kGridY, 1});
    writeXml(flat, dir.file("flat.vti"));
    writeLegacy(flat, dir.file("flat.vtk"), true);
    for (const std::string name : {"flat.vti", "flat.vtk"}) {
        const Error e = errorFrom<VtkReader>(selection({dir.file(name)}));
        EXPECT_EQ(e.kind(), ErrorKind::NotThreeDimensional) << name;
        EXPECT_TRUE(contains(e, "6 x 5 x 1")) << e.what();
    }
}

TEST(VtkReader, TruncatedFilesAreCorruptAndPrintNothing) {
    ensil::test::TempDir dir;
    const std::array<int, 3> dims{20, 20, 20};
    auto img = image(dims);
    addScalars<vtkFloatArray>(*img, "f", 0, dims);
    writeLegacy(img, dir.file("binary.vtk"), true);
    writeLegacy(img, dir.file("text.vtk"), false);
    writeXml(img, dir.file("image.vti"));
    for (const std::string name : {"binary.vtk", "text.vtk", "image.vti"}) {
        const std::string path = dir.file(name);
        std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
        testing::internal::CaptureStderr();
        const Error e = errorFrom<VtkReader>(selection({path}));
        const std::string printed = testing::internal::GetCapturedStderr();
        EXPECT_EQ(e.kind(), ErrorKind::CorruptFile) << name << ": " << e.what();
        EXPECT_TRUE(contains(e, path)) << e.what();
        EXPECT_EQ(printed, "") << name;
    }
}

TEST(VtkReader, FilesThatAreNotVtkImagesAreRefused) {
    ensil::test::TempDir dir;
    const std::string text = dir.file("notes.vtk");
    std::ofstream(text) << "x,y,value\n0,0,1.5\n";
    const std::string mesh = dir.file("mesh.vtk");
    vtkNew<vtkPolyData> polyData;
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetInputData(polyData);
    writer->SetFileName(mesh.c_str());
    ASSERT_EQ(writer->Write(), 1);

    EXPECT_FALSE(VtkReader().recognizes(text));
    EXPECT_TRUE(VtkReader().recognizes(mesh));
    const Error notVtk = errorFrom<VtkReader>(selection({text}));
    EXPECT_EQ(notVtk.kind(), ErrorKind::UnsupportedFormat);
    EXPECT_TRUE(contains(notVtk, text)) << notVtk.what();
    const Error polygons = errorFrom<VtkReader>(selection({mesh}));
    EXPECT_EQ(polygons.kind(), ErrorKind::UnsupportedFormat);
    EXPECT_TRUE(contains(polygons, "POLYDATA")) << polygons.what();
    EXPECT_EQ(errorFrom<VtkReader>(selection({dir.file("absent.vti")})).kind(),
              ErrorKind::FileNotFound);
}

TEST(VtkReader, ProgressRisesToOneAndAStopBetweenMembersCancels) {
    ensil::test::TempDir dir;
    std::vector<std::string> paths;
    for (int m = 0; m < 4; ++m) {
        auto img = image();
        addScalars<vtkFloatArray>(*img, "f", m, {kGridX, kGridY, kGridZ});
        paths.push_back(dir.file("m" + std::to_string(m) + ".vti"));
        writeXml(img, paths.back());
    }
    std::vector<double> seen;
    (void)VtkReader().read(selection(paths), {}, [&](double f) { seen.push_back(f); });
    EXPECT_TRUE(std::ranges::is_sorted(seen));
    ASSERT_FALSE(seen.empty());
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);

    std::stop_source stop;
    std::vector<double> beforeCancel;
    const auto cancelAfterFirst = [&](double f) {
        beforeCancel.push_back(f);
        if (f > 0.0) stop.request_stop();
    };
    EXPECT_THROW((void)VtkReader().read(selection(paths), stop.get_token(), cancelAfterFirst),
                 Cancelled);
    EXPECT_EQ(beforeCancel, (std::vector<double>{0.0, 0.25}));
}

TEST(VtkReader, ReadsTheIronProteinVolume) {
    const std::string path = ENSIL_SHARED_DATA_DIR "/ironProt.vtk";
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    ASSERT_TRUE(VtkReader().recognizes(path));
    const Ensemble e = VtkReader().read(selection({path}), {}, {});
    ASSERT_EQ(e.memberCount(), 1u);
    EXPECT_EQ(e.grid.nx(), 68u);
    EXPECT_EQ(e.grid.ny(), 68u);
    EXPECT_EQ(e.grid.nz(), 68u);
    EXPECT_EQ(e.members[0].name, "ironProt");
    EXPECT_EQ(e.variable, "scalars");
    const auto [low, high] = std::ranges::minmax(e.members[0].values);
    EXPECT_GE(low, 0.0f);
    EXPECT_LE(high, 255.0f);
    EXPECT_LT(low, high);
    const EnsembleDescription d = VtkReader().describe(selection({path}));
    EXPECT_EQ(d.format, "VTK legacy");
    EXPECT_EQ(d.bytes(), 68u * 68u * 68u * sizeof(float));
}

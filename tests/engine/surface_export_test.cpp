// Surfaces written for other tools, read back by those tools' own libraries: VTK's XML reader
// (what ParaView uses) for .vtm/.vtp, OpenMesh's readers for PLY (with its per-vertex
// properties), OBJ and STL.
#include "engine/surface_export.h"

#include <gtest/gtest.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <fstream>
#include <memory>

#include "data/demo_ensemble.h"
#include "data/error.h"
#include "engine/preprocess_run.h"
#include "preprocessing/mesh_packing.h"
#include "tests/support/temp_dir.h"

namespace ensil {
namespace {

struct SmallDemo {
    engine::PreprocessResult result;
};

// Six members on a small grid, preprocessed at 30 m/s with three clusters: every member, the
// mean and the summary surfaces have triangles.
const SmallDemo& smallDemo() {
    static const SmallDemo demo = [] {
        data::DemoEnsembleParams params;
        params.members = 6;
        params.nx = 48;
        params.ny = 32;
        params.nz = 8;
        SmallDemo d;
        engine::PreprocessRequest request;
        request.isovalue = 30.0;
        request.clusters = 3;
        request.clustersGiven = true;
        d.result = engine::preprocessEnsemble(
            std::make_shared<const data::Ensemble>(data::makeDemoEnsemble(params).ensemble),
            request, [](const std::string&, const std::string&) {});
        return d;
    }();
    return demo;
}

using ReadMesh = OpenMesh::TriMesh_ArrayKernelT<>;

TEST(SurfaceExport, ParaViewsReaderFindsEverySurfaceWithItsTrianglesNameAndCluster) {
    const engine::PreprocessResult& r = smallDemo().result;
    ASSERT_FALSE(r.meshes.bandInner.indices.empty());
    test::TempDir dir;
    const engine::ExportedSurfaces written = engine::exportSurfaces(
        engine::surfaceSetOf(r), engine::SurfaceFormat::Vtp, dir.path() / "out");
    ASSERT_FALSE(written.files.empty());
    EXPECT_EQ(written.files.front().extension(), ".vtm");

    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName(written.files.front().c_str());
    reader->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    ASSERT_NE(blocks, nullptr);
    const std::size_t members = r.meshes.members.size();
    ASSERT_EQ(blocks->GetNumberOfBlocks(), members + 4);  // + mean, P = 0.5, band inner, outer
    EXPECT_EQ(written.surfaces, members + 4);
    const data::Grid& g = r.ensemble->grid;
    std::size_t triangles = 0;
    for (unsigned b = 0; b < blocks->GetNumberOfBlocks(); ++b) {
        auto* poly = vtkPolyData::SafeDownCast(blocks->GetBlock(b));
        ASSERT_NE(poly, nullptr) << "block " << b;
        const data::PackedMesh& mesh = b < members        ? r.meshes.members[b]
                                       : b == members     ? r.meshes.mean
                                       : b == members + 1 ? r.meshes.probability
                                       : b == members + 2 ? r.meshes.bandInner
                                                          : r.meshes.bandOuter;
        EXPECT_EQ(poly->GetNumberOfPolys(), static_cast<vtkIdType>(mesh.indices.size() / 3))
            << "block " << b;
        EXPECT_EQ(poly->GetNumberOfPoints(), static_cast<vtkIdType>(mesh.vertices.size()));
        triangles += mesh.indices.size() / 3;
        // In the data's coordinates: degrees and hPa, inside the axes.
        double bounds[6];
        poly->GetBounds(bounds);
        for (int a = 0; a < 3; ++a) {
            EXPECT_GE(bounds[2 * a], g.axis(a).minValue() - 1e-6) << "block " << b;
            EXPECT_LE(bounds[2 * a + 1], g.axis(a).maxValue() + 1e-6) << "block " << b;
        }
        vtkDataArray* cluster = poly->GetPointData()->GetArray("cluster");
        vtkDataArray* member = poly->GetPointData()->GetArray("member");
        ASSERT_NE(cluster, nullptr);
        ASSERT_NE(member, nullptr);
        ASSERT_NE(poly->GetPointData()->GetArray("outlyingness"), nullptr);
        const char* name = blocks->GetMetaData(b)->Get(vtkCompositeDataSet::NAME());
        if (b < members) {
            EXPECT_EQ(cluster->GetTuple1(0), r.clusterNumbers[b]);
            EXPECT_EQ(member->GetTuple1(0), b + 1);
            EXPECT_EQ(std::string(name), "member " + std::to_string(b + 1));
        } else {
            EXPECT_EQ(cluster->GetTuple1(0), 0);
        }
    }
    EXPECT_EQ(std::string(blocks->GetMetaData(members)->Get(vtkCompositeDataSet::NAME())), "mean");
    EXPECT_EQ(written.triangles, triangles);
}

TEST(SurfaceExport, APlyReadBackByOpenMeshKeepsItsPerVertexProperties) {
    const engine::PreprocessResult& r = smallDemo().result;
    test::TempDir dir;
    const engine::ExportedSurfaces written =
        engine::exportSurfaces(engine::surfaceSetOf(r), engine::SurfaceFormat::Ply, dir.path());
    ASSERT_EQ(written.files.size(), r.meshes.members.size() + 4);
    const std::filesystem::path second = dir.path() / "wind_speed_iso30_member02.ply";
    ASSERT_TRUE(std::filesystem::exists(second)) << written.files.front();

    ReadMesh mesh;
    OpenMesh::VPropHandleT<int> member, cluster;
    OpenMesh::VPropHandleT<float> outlyingness;
    mesh.add_property(member, "member");
    mesh.add_property(cluster, "cluster");
    mesh.add_property(outlyingness, "outlyingness");
    OpenMesh::IO::Options options = OpenMesh::IO::Options::Custom;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(mesh, second.string(), options));
    EXPECT_EQ(mesh.n_faces(), r.meshes.members[1].indices.size() / 3);
    EXPECT_EQ(mesh.n_vertices(), r.meshes.members[1].vertices.size());
    ASSERT_TRUE(mesh.get_property_handle(member, "member"));
    ASSERT_TRUE(mesh.get_property_handle(cluster, "cluster"));
    const auto v = *mesh.vertices_begin();
    EXPECT_EQ(mesh.property(member, v), 2);
    EXPECT_EQ(mesh.property(cluster, v), r.clusterNumbers[1]);
}

TEST(SurfaceExport, ObjAndStlCarryEveryTriangle) {
    const engine::PreprocessResult& r = smallDemo().result;
    for (const auto format : {engine::SurfaceFormat::Obj, engine::SurfaceFormat::Stl}) {
        test::TempDir dir;
        engine::SurfaceSet set = engine::surfaceSetOf(r);
        set.members = {0};
        set.context = false;
        const engine::ExportedSurfaces written = engine::exportSurfaces(set, format, dir.path());
        ASSERT_EQ(written.files.size(), 1u);
        ReadMesh mesh;
        ASSERT_TRUE(OpenMesh::IO::read_mesh(mesh, written.files.front().string()));
        EXPECT_EQ(mesh.n_faces(), r.meshes.members[0].indices.size() / 3)
            << engine::surfaceFormatName(format);
    }
}

TEST(SurfaceExport, AFileWhereTheFolderShouldBeIsNamedAndNothingIsWritten) {
    test::TempDir dir;
    const std::filesystem::path file = dir.path() / "taken";
    std::ofstream(file) << "not a folder";
    try {
        (void)engine::exportSurfaces(engine::surfaceSetOf(smallDemo().result),
                                     engine::SurfaceFormat::Vtp, file);
        FAIL() << "a file was taken for a folder";
    } catch (const data::Error& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
}

TEST(SurfaceExport, OneSurfaceGoesToTheFileNamedInTheFormatItsSuffixSays) {
    const engine::PreprocessResult& r = smallDemo().result;
    const engine::SurfaceSet set = engine::surfaceSetOf(r);
    test::TempDir dir;
    const std::filesystem::path vtp = dir.path() / "third.vtp";
    EXPECT_EQ(engine::writeSurface(set, r.meshes.members[2], vtp), 0u);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(vtp.c_str());
    reader->Update();
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPolys(),
              static_cast<vtkIdType>(r.meshes.members[2].indices.size() / 3));
    vtkDataArray* member = reader->GetOutput()->GetPointData()->GetArray("member");
    ASSERT_NE(member, nullptr);
    EXPECT_EQ(member->GetTuple1(0), 3);
    const std::filesystem::path mean = dir.path() / "mean.stl";
    EXPECT_EQ(engine::writeSurface(set, r.meshes.mean, mean), 0u);
    ReadMesh read;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(read, mean.string()));
    EXPECT_EQ(read.n_faces(), r.meshes.mean.indices.size() / 3);
    const data::PackedMesh stranger;
    EXPECT_THROW((void)engine::writeSurface(set, stranger, dir.path() / "x.ply"), data::Error);
    EXPECT_THROW((void)engine::writeSurface(set, r.meshes.mean, dir.path() / "x.vtm"), data::Error);
}

TEST(SurfaceExport, InTheDisplayFrameTheVerticesLieInTheWorkbenchsBox) {
    const engine::PreprocessResult& r = smallDemo().result;
    engine::SurfaceSet set = engine::surfaceSetOf(r);
    set.displayFrame = data::DisplayFrame(r.ensemble->grid, 1.0F);
    test::TempDir dir;
    const std::filesystem::path vtp = dir.path() / "box.vtp";
    ASSERT_EQ(engine::writeSurface(set, r.meshes.members[0], vtp), 0u);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(vtp.c_str());
    reader->Update();
    double bounds[6];
    reader->GetOutput()->GetBounds(bounds);
    const glm::vec3 box = set.displayFrame->boxMax();
    for (int a = 0; a < 3; ++a) {
        EXPECT_GE(bounds[2 * a], -1e-4) << "axis " << a;
        EXPECT_LE(bounds[2 * a + 1], box[a] + 1e-4) << "axis " << a;
    }
    // Not the data's degrees: the longitudes span 120 degrees, the box about 1.
    EXPECT_LT(bounds[1] - bounds[0], 10.0);
    const glm::vec3 first = set.displayFrame->indexToDisplay(
        prep::unpackPosition(r.meshes.members[0], r.meshes.members[0].vertices[0]));
    double p[3];
    reader->GetOutput()->GetPoint(0, p);
    EXPECT_NEAR(p[0], first.x, 1e-5);
    EXPECT_NEAR(p[2], first.z, 1e-5);
}

TEST(SurfaceExport, FormatsAreNamedAsTheCommandLineTakesThem) {
    EXPECT_EQ(engine::surfaceFormatNamed("PLY"), engine::SurfaceFormat::Ply);
    EXPECT_EQ(engine::surfaceFormatNamed("vtp"), engine::SurfaceFormat::Vtp);
    EXPECT_FALSE(engine::surfaceFormatNamed("vtk").has_value());
    EXPECT_EQ(engine::surfaceFormatOfFile("/data/jet.vtm"), engine::SurfaceFormat::Vtp);
    EXPECT_EQ(engine::surfaceFormatOfFile("jet.stl"), engine::SurfaceFormat::Stl);
    EXPECT_FALSE(engine::surfaceFormatOfFile("jet").has_value());
}

}  // namespace
}  // namespace ensil

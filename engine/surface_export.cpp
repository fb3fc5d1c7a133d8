#include "engine/surface_export.h"

#include <vtkCellArray.h>
#include <vtkCompositeDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <system_error>

#include "data/error.h"
#include "data/job.h"
#include "preprocessing/mesh_packing.h"

namespace ensil::engine {
namespace {

// One surface, unpacked: positions in the chosen frame and the values each vertex carries.
struct Surface {
    std::string label;     // the block name: "member 3 (ens03)", "mean", ...
    std::string fileName;  // the name part of its own file: "member03_ens03", "mean"
    int member = 0;        // from 1; 0 for a summary surface
    int cluster = 0;       // as the legend numbers it; 0 where none
    double depth = std::numeric_limits<double>::quiet_NaN();
    const data::PackedMesh* mesh = nullptr;
};

// Letters, digits, '-', '_' and '.' kept; anything else (spaces, slashes) becomes '_', so a
// member name cannot step out of the directory or trip a tool's parser.
std::string safeName(const std::string& text) {
    std::string out;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        out += (std::isalnum(u) != 0 || c == '-' || c == '_' || c == '.') ? c : '_';
    }
    return out.empty() ? std::string("unnamed") : out;
}

// "30", "0.5", "-2.25e-05": the isovalue as it reads in a file name.
std::string isovalueText(float isovalue) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", static_cast<double>(isovalue));
    return buffer;
}

std::vector<Surface> surfacesOf(const SurfaceSet& set) {
    const data::MeshSet& meshes = *set.meshes;
    std::vector<Surface> out;
    std::vector<int> chosen = set.members;
    if (chosen.empty()) {
        for (std::size_t i = 0; i < meshes.members.size(); ++i)
            chosen.push_back(static_cast<int>(i));
    }
    const int digits = meshes.members.size() >= 100 ? 3 : 2;
    for (const int i : chosen) {
        if (i < 0 || static_cast<std::size_t>(i) >= meshes.members.size()) {
            throw data::Error(data::ErrorKind::InvalidArgument,
                              "member " + std::to_string(i + 1) + " does not exist (there are " +
                                  std::to_string(meshes.members.size()) + ")");
        }
        const auto index = static_cast<std::size_t>(i);
        Surface s;
        s.member = i + 1;
        // A name that only says the number again ("member 3", "3") is not repeated.
        const std::string numbered = "member " + std::to_string(i + 1);
        std::string name = index < set.memberNames.size() ? set.memberNames[index] : "";
        if (name == numbered || name == std::to_string(i + 1)) name.clear();
        s.label = name.empty() ? numbered : numbered + " (" + name + ")";
        char number[16];
        std::snprintf(number, sizeof number, "%0*d", digits, i + 1);
        s.fileName = "member" + std::string(number) + (name.empty() ? "" : "_" + safeName(name));
        if (index < set.clusterNumbers.size()) s.cluster = set.clusterNumbers[index];
        if (index < set.depth.size()) s.depth = set.depth[index];
        s.mesh = &meshes.members[index];
        out.push_back(s);
    }
    if (set.context) {
        const auto summary = [&](const char* label, const char* file, const data::PackedMesh& m) {
            Surface s;
            s.label = label;
            s.fileName = file;
            s.mesh = &m;
            out.push_back(s);
        };
        summary("mean", "mean", meshes.mean);
        summary("P = 0.5", "p50", meshes.probability);
        summary("band inner", "band_inner", meshes.bandInner);
        summary("band outer", "band_outer", meshes.bandOuter);
    }
    std::erase_if(out, [](const Surface& s) { return s.mesh->indices.empty(); });
    return out;
}

// A vertex's position: grid index space to the axes' values, or to the display frame.
glm::dvec3 placed(const SurfaceSet& set, const glm::vec3& index) {
    if (set.displayFrame) return glm::dvec3(set.displayFrame->indexToDisplay(index));
    const data::Grid& g = *set.grid;
    return {g.x().valueAt(index.x), g.y().valueAt(index.y), g.z().valueAt(index.z)};
}

vtkSmartPointer<vtkPolyData> polyDataOf(const SurfaceSet& set, const Surface& s) {
    const data::PackedMesh& mesh = *s.mesh;
    const auto n = static_cast<vtkIdType>(mesh.vertices.size());
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(n);
    const auto named = [n](auto array, const char* name, int components = 1) {
        array->SetName(name);
        array->SetNumberOfComponents(components);
        array->SetNumberOfTuples(n);
        return array;
    };
    vtkNew<vtkIntArray> member, cluster;
    vtkNew<vtkFloatArray> depth, outlyingness, kappa1, kappa2, normals;
    named(member.Get(), "member");
    named(cluster.Get(), "cluster");
    named(depth.Get(), "depth");
    named(outlyingness.Get(), "outlyingness");
    named(kappa1.Get(), "kappa1");
    named(kappa2.Get(), "kappa2");
    named(normals.Get(), "normals_display", 3);
    for (vtkIdType v = 0; v < n; ++v) {
        const data::PackedVertex& pv = mesh.vertices[static_cast<std::size_t>(v)];
        const glm::dvec3 p = placed(set, prep::unpackPosition(mesh, pv));
        points->SetPoint(v, p.x, p.y, p.z);
        member->SetValue(v, s.member);
        cluster->SetValue(v, s.cluster);
        depth->SetValue(v, static_cast<float>(s.depth));
        outlyingness->SetValue(v, prep::unpackHalf(pv.outlyingness) * mesh.outlyingnessScale);
        kappa1->SetValue(v, prep::unpackHalf(pv.kappa1));
        kappa2->SetValue(v, prep::unpackHalf(pv.kappa2));
        const glm::vec3 normal = prep::unpackUnitVector(pv.normal);
        normals->SetTypedTuple(v, &normal.x);
    }
    vtkNew<vtkCellArray> triangles;
    const std::size_t count = mesh.indices.size() / 3;
    triangles->AllocateExact(static_cast<vtkIdType>(count), static_cast<vtkIdType>(count * 3));
    for (std::size_t t = 0; t < count; ++t) {
        const vtkIdType ids[3] = {mesh.indices[3 * t], mesh.indices[3 * t + 1],
                                  mesh.indices[3 * t + 2]};
        triangles->InsertNextCell(3, ids);
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetPolys(triangles);
    vtkPointData* pd = poly->GetPointData();
    pd->AddArray(member);
    pd->AddArray(cluster);
    pd->AddArray(depth);
    pd->AddArray(outlyingness);
    pd->AddArray(kappa1);
    pd->AddArray(kappa2);
    pd->AddArray(normals);
    pd->SetActiveScalars("cluster");
    return poly;
}

// The isovalue and variable travel with the data as field data, for ParaView's information tab.
void describe(vtkMultiBlockDataSet& blocks, const SurfaceSet& set) {
    vtkNew<vtkDoubleArray> iso;
    iso->SetName("isovalue");
    iso->InsertNextValue(set.meshes->isovalue);
    vtkNew<vtkStringArray> variable;
    variable->SetName("variable");
    variable->InsertNextValue(set.variable + (set.units.empty() ? "" : " (" + set.units + ")"));
    vtkNew<vtkStringArray> axes;
    axes->SetName("coordinates");
    const data::Grid& g = *set.grid;
    axes->InsertNextValue(set.displayFrame
                              ? std::string("the workbench's display frame")
                              : g.x().name + " (" + g.x().units + "), " + g.y().name + " (" +
                                    g.y().units + "), " + g.z().name + " (" + g.z().units + ")");
    blocks.GetFieldData()->AddArray(iso);
    blocks.GetFieldData()->AddArray(variable);
    blocks.GetFieldData()->AddArray(axes);
}

void writeVtm(const SurfaceSet& set, const std::vector<Surface>& surfaces,
              const std::filesystem::path& file, const std::stop_token& stop,
              const data::Progress& progress) {
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(static_cast<unsigned>(surfaces.size()));
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        data::throwIfStopped(stop);
        const auto b = static_cast<unsigned>(i);
        blocks->SetBlock(b, polyDataOf(set, surfaces[i]));
        blocks->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(), surfaces[i].label.c_str());
        // Building the blocks is about half the work, writing them the other half.
        if (progress)
            progress(0.5 * static_cast<double>(i + 1) / static_cast<double>(surfaces.size()));
    }
    describe(*blocks.Get(), set);
    vtkNew<vtkXMLMultiBlockDataWriter> writer;
    writer->SetFileName(file.c_str());
    writer->SetInputData(blocks);
    writer->SetDataModeToAppended();
    // zlib (VTK's default): the demo's 51 surfaces in 2.2 MB instead of 6.0, in 146 ms instead
    // of 78 (docs/benchmarks.md).
    writer->SetCompressorTypeToZLib();
    if (writer->Write() != 1) {
        throw data::Error(data::ErrorKind::WriteFailed,
                          "could not write '" + file.string() + "' (VTK's XML writer failed)");
    }
}

// OpenMesh's PLY writer writes a custom property when the mesh holds it persistent and the
// options say Custom; the types below are what PLY names float and int.
using ExportMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// OpenMesh's writers say "[OBJWriter] : write file" on its log stream for every file; a
// command's output is no place for that. Its error stream stays on.
void quietenOpenMesh() {
    static std::once_flag once;
    std::call_once(once, [] {
        omlog().disable();
        omout().disable();
    });
}

// Returns the triangles OpenMesh refused: it keeps a manifold mesh and drops a face that
// would make an edge complex (decimation can leave a few where sheets of a surface touch).
std::size_t writeWithOpenMesh(const SurfaceSet& set, const Surface& s, SurfaceFormat format,
                              const std::filesystem::path& file) {
    quietenOpenMesh();
    const data::PackedMesh& mesh = *s.mesh;
    ExportMesh out;
    out.reserve(mesh.vertices.size(), mesh.indices.size() / 2, mesh.indices.size() / 3);
    std::vector<ExportMesh::VertexHandle> handles;
    handles.reserve(mesh.vertices.size());
    for (const data::PackedVertex& v : mesh.vertices) {
        const glm::dvec3 p = placed(set, prep::unpackPosition(mesh, v));
        handles.push_back(out.add_vertex(ExportMesh::Point(
            static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z))));
    }
    std::size_t refused = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const auto face = out.add_face(handles[mesh.indices[t]], handles[mesh.indices[t + 1]],
                                       handles[mesh.indices[t + 2]]);
        if (!face.is_valid()) ++refused;
    }
    OpenMesh::IO::Options options = OpenMesh::IO::Options::Binary;
    if (format == SurfaceFormat::Ply) {
        OpenMesh::VPropHandleT<int> member, cluster;
        OpenMesh::VPropHandleT<float> depth, outlyingness, kappa1, kappa2;
        out.add_property(member, "member");
        out.add_property(cluster, "cluster");
        out.add_property(depth, "depth");
        out.add_property(outlyingness, "outlyingness");
        out.add_property(kappa1, "kappa1");
        out.add_property(kappa2, "kappa2");
        for (const auto h : {member, cluster}) out.property(h).set_persistent(true);
        for (const auto h : {depth, outlyingness, kappa1, kappa2}) {
            out.property(h).set_persistent(true);
        }
        for (std::size_t i = 0; i < handles.size(); ++i) {
            const data::PackedVertex& v = mesh.vertices[i];
            const ExportMesh::VertexHandle h = handles[i];
            out.property(member, h) = s.member;
            out.property(cluster, h) = s.cluster;
            out.property(depth, h) = static_cast<float>(s.depth);
            out.property(outlyingness, h) =
                prep::unpackHalf(v.outlyingness) * mesh.outlyingnessScale;
            out.property(kappa1, h) = prep::unpackHalf(v.kappa1);
            out.property(kappa2, h) = prep::unpackHalf(v.kappa2);
        }
        options += OpenMesh::IO::Options::Custom;
    } else if (format == SurfaceFormat::Obj) {
        options = OpenMesh::IO::Options::Default;  // OBJ is text only
    }
    if (!OpenMesh::IO::write_mesh(out, file.string(), options)) {
        throw data::Error(data::ErrorKind::WriteFailed,
                          "could not write '" + file.string() + "' (OpenMesh's writer failed)");
    }
    return refused;
}

}  // namespace

SurfaceSet surfaceSetOf(const PreprocessResult& result) {
    const data::Ensemble& e = *result.ensemble;
    SurfaceSet set;
    set.meshes = &result.meshes;
    set.grid = &e.grid;
    set.variable = e.variable;
    set.units = e.units;
    for (const data::Member& m : e.members) set.memberNames.push_back(m.name);
    set.clusterNumbers = result.clusterNumbers;
    set.depth = result.boxplot.depth;
    return set;
}

std::optional<SurfaceFormat> surfaceFormatNamed(const std::string& name) {
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const SurfaceFormat f :
         {SurfaceFormat::Vtp, SurfaceFormat::Ply, SurfaceFormat::Obj, SurfaceFormat::Stl}) {
        if (surfaceFormatName(f) == lower) return f;
    }
    return std::nullopt;
}

std::string surfaceFormatName(SurfaceFormat format) {
    switch (format) {
        case SurfaceFormat::Vtp:
            return "vtp";
        case SurfaceFormat::Ply:
            return "ply";
        case SurfaceFormat::Obj:
            return "obj";
        case SurfaceFormat::Stl:
            return "stl";
    }
    return "vtp";
}

std::string surfaceFormatNames() { return "vtp, ply, obj, stl"; }

std::optional<SurfaceFormat> surfaceFormatOfFile(const std::filesystem::path& file) {
    std::string suffix = file.extension().string();
    if (suffix.empty()) return std::nullopt;
    suffix.erase(0, 1);
    return surfaceFormatNamed(suffix == "vtm" || suffix == "VTM" ? std::string("vtp") : suffix);
}

ExportedSurfaces exportSurfaces(const SurfaceSet& set, SurfaceFormat format,
                                const std::filesystem::path& directory, const std::stop_token& stop,
                                const data::Progress& progress) {
    if (set.meshes == nullptr || set.grid == nullptr) {
        throw data::Error(data::ErrorKind::InvalidArgument, "no surfaces to export");
    }
    const std::vector<Surface> surfaces = surfacesOf(set);
    if (surfaces.empty()) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "no surface to export: none of the chosen members reaches the "
                          "isovalue " +
                              isovalueText(set.meshes->isovalue));
    }
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory)) {
        throw data::Error(data::ErrorKind::WriteFailed,
                          "cannot write surfaces into '" + directory.string() + "'" +
                              (error ? ": " + error.message() : std::string(": not a folder")));
    }
    const std::string stem = !set.stem.empty()
                                 ? safeName(set.stem)
                                 : safeName(set.variable.empty() ? "surfaces" : set.variable) +
                                       "_iso" + isovalueText(set.meshes->isovalue);
    ExportedSurfaces result;
    for (const Surface& s : surfaces) result.triangles += s.mesh->indices.size() / 3;
    result.surfaces = surfaces.size();
    if (format == SurfaceFormat::Vtp) {
        const std::filesystem::path index = directory / (stem + ".vtm");
        writeVtm(set, surfaces, index, stop, progress);
        result.files.push_back(index);
        for (const auto& piece : std::filesystem::directory_iterator(directory / stem, error)) {
            result.files.push_back(piece.path());
        }
        std::sort(result.files.begin() + 1, result.files.end());
        return result;
    }
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        const Surface& s = surfaces[i];
        data::throwIfStopped(stop);
        if (progress) progress(static_cast<double>(i) / static_cast<double>(surfaces.size()));
        const std::filesystem::path file =
            directory / (stem + "_" + s.fileName + "." + surfaceFormatName(format));
        result.trianglesLeftOut += writeWithOpenMesh(set, s, format, file);
        result.files.push_back(file);
    }
    return result;
}

std::size_t writeSurface(const SurfaceSet& set, const data::PackedMesh& mesh,
                         const std::filesystem::path& file) {
    const auto format = surfaceFormatOfFile(file);
    if (!format || file.extension() == ".vtm") {
        throw data::Error(
            data::ErrorKind::InvalidArgument,
            "'" + file.string() + "': name a file ending in .vtp, .ply, .obj or .stl");
    }
    SurfaceSet all = set;
    all.members.clear();
    all.context = true;
    std::vector<Surface> surfaces = surfacesOf(all);
    const auto found = std::find_if(surfaces.begin(), surfaces.end(),
                                    [&](const Surface& s) { return s.mesh == &mesh; });
    if (found == surfaces.end()) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "'" + file.string() + "': the mesh is empty or not one of this result's");
    }
    if (*format != SurfaceFormat::Vtp) return writeWithOpenMesh(set, *found, *format, file);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(file.c_str());
    writer->SetInputData(polyDataOf(set, *found));
    writer->SetDataModeToAppended();
    writer->SetCompressorTypeToZLib();
    if (writer->Write() != 1) {
        throw data::Error(data::ErrorKind::WriteFailed,
                          "could not write '" + file.string() + "' (VTK's XML writer failed)");
    }
    return 0;
}

}  // namespace ensil::engine

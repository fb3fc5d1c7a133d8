// The isosurfaces of one isovalue written for other tools: ParaView (VTK XML: a .vtp per
// surface gathered by a .vtm, through VTK's writers), MeshLab, CloudCompare and Blender (PLY,
// binary, with per-vertex properties; OBJ; STL; through OpenMesh's IO). Vertices are in the
// data's own coordinates (each axis's values: longitude, latitude and pressure or height, or a
// projection's metres), or, asked for, in the frame the workbench draws in. Any thread.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "data/display_frame.h"
#include "data/grid.h"
#include "data/job.h"
#include "data/packed_mesh.h"
#include "engine/preprocess_run.h"

namespace ensil::engine {

enum class SurfaceFormat { Vtp, Ply, Obj, Stl };

// "vtp", "ply", "obj", "stl" (any case); none for anything else.
std::optional<SurfaceFormat> surfaceFormatNamed(const std::string& name);
std::string surfaceFormatName(SurfaceFormat format);
// "vtp, ply, obj, stl": for help texts and messages.
std::string surfaceFormatNames();
// The format a file name's suffix asks for: .vtm and .vtp (VTK XML), .ply, .obj, .stl.
std::optional<SurfaceFormat> surfaceFormatOfFile(const std::filesystem::path& file);

// What to write: the meshes of one isovalue and what is known of each member.
struct SurfaceSet {
    const data::MeshSet* meshes = nullptr;
    const data::Grid* grid = nullptr;
    std::string variable;  // for the files' metadata, and their names when `stem` is empty
    std::string units;
    std::vector<std::string> memberNames;  // one per member of meshes->members
    std::vector<int> clusterNumbers;       // per member, as the legend numbers them; empty: none
    std::vector<double> depth;             // per member (contour boxplot); empty: none
    std::vector<int> members;              // which members to write, by index; empty: all
    bool context = true;                   // also the mean and the summary surfaces
    // The files' names begin with it: "jet" gives jet.vtm, jet_member03.ply; empty:
    // VARIABLE_isoVALUE.
    std::string stem;
    // Set: vertices (and normals) in the workbench's display frame instead of data coordinates.
    std::optional<data::DisplayFrame> displayFrame;
};

// A preprocessing result's surfaces, every member with its name, cluster number and depth, the
// summaries with them; it points into `result`, which must outlive it.
SurfaceSet surfaceSetOf(const PreprocessResult& result);

struct ExportedSurfaces {
    std::vector<std::filesystem::path> files;  // every file written, the index first if any
    std::size_t surfaces = 0;                  // meshes written (empty ones are skipped)
    std::size_t triangles = 0;
    // PLY, OBJ, STL: triangles OpenMesh refused to add (it keeps meshes manifold, and a face
    // where two sheets of a decimated surface touch would make an edge complex); 0 for VTP.
    std::size_t trianglesLeftOut = 0;
};

// Writes into `directory` (made when missing) files named from `stem` (else the variable and
// isovalue): VTP: VARIABLE_isoVALUE.vtm and its folder of .vtp pieces, one block per surface named
// for it ("member 3 (ens03)", "mean", "P = 0.5", "band inner", "band outer"); PLY, OBJ, STL: a file
// per surface, VARIABLE_isoVALUE_member03_NAME.ply, ..._mean.ply. Per-vertex values (VTP point
// data, PLY properties): member (index from 1; 0 for a summary surface), cluster (as the legend
// numbers it; 0 where none), depth, outlyingness, kappa1, kappa2; VTP also the normals in the
// display frame. OBJ and STL carry positions only. Refuses (data::Error, naming the file) a
// directory it cannot write to and a writer that fails; throws data::Cancelled when `stop` is asked
// for between surfaces. `progress` hears the share of surfaces done.
ExportedSurfaces exportSurfaces(const SurfaceSet& set, SurfaceFormat format,
                                const std::filesystem::path& directory,
                                const std::stop_token& stop = {},
                                const data::Progress& progress = {});

// One surface of `set` (a member's mesh or a summary's, found by address in set.meshes) into
// `file`, in the format its suffix asks for (.vtp, .ply, .obj, .stl), with the per-vertex
// values above. Returns the triangles OpenMesh refused (see trianglesLeftOut). Refuses a
// suffix it does not know and a mesh not in the set (data::Error).
std::size_t writeSurface(const SurfaceSet& set, const data::PackedMesh& mesh,
                         const std::filesystem::path& file);

}  // namespace ensil::engine

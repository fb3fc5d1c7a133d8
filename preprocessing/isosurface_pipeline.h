// Everything the renderer needs for one isovalue: every member's isosurface and the mean
// member's, each meshed, optionally decimated, given per-vertex attributes and packed. One
// task per member runs all stages (oneTBB, with marching cubes itself parallel over layers),
// so full-resolution meshes never pile up. A new isovalue needs nothing precomputed but the
// ensemble moments. Pure function; any thread.
#pragma once

#include <stop_token>
#include <vector>

#include "data/display_frame.h"
#include "data/ensemble.h"
#include "data/job.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/mesh_packing.h"
#include "preprocessing/vertex_attributes.h"

namespace ensil::prep {

struct PipelineOptions {
    float isovalue = 0.0F;
    bool decimate = true;
    float maxErrorCells = 0.25F;  // decimation error bound, in grid cells
};

// Wall-clock seconds, apportioned among the stages by their share of the threads' busy time
// (the stages of different members overlap).
struct StageSeconds {
    double meshes = 0, decimation = 0, attributes = 0;
};

// The meshes of one isovalue (a data::MeshSet, what the renderer and the cache take) and how
// they were built. The renderer takes the MeshSet part as it is: nothing is copied field by
// field.
struct IsovalueMeshes : data::MeshSet {
    StageSeconds seconds;
    std::size_t trianglesExtracted = 0;  // before decimation, all members and the mean
    std::size_t triangles = 0;           // after
    std::size_t vertices = 0;
    float worstErrorCells = 0.0F;  // largest decimation error estimate over the meshes
};

// What meshing one field cost and gave.
struct FieldMeshStats {
    StageSeconds seconds;
    std::size_t extracted = 0, triangles = 0, vertices = 0;
    float error = 0.0F;  // decimation error estimate, in cells
};
struct MeshedField {
    data::PackedMesh mesh;
    FieldMeshStats stats;
};

// One field's isosurface through every stage: marching cubes, decimation, the per-vertex
// attributes (outlyingness from `moments`, none when null) and packing. Throws data::Cancelled.
MeshedField meshField(const data::Grid& grid, const data::FieldValues& field, float isovalue,
                      const AxisTables& axes, const EnsembleMoments* moments,
                      const PipelineOptions& options, const std::stop_token& stop = {});

// The meshes' totals (triangles, vertices, worst error) and each stage's share of `wallSeconds`
// from the fields' statistics: the stages of different fields ran interleaved on all threads.
void summariseMeshes(IsovalueMeshes& meshes, const std::vector<FieldMeshStats>& stats,
                     double wallSeconds);

// Throws data::Cancelled.
IsovalueMeshes buildIsovalueMeshes(const data::Ensemble& ensemble, const EnsembleMoments& moments,
                                   const data::DisplayFrame& frame, const PipelineOptions& options,
                                   const std::stop_token& stop = {},
                                   const data::Progress& progress = {});

}  // namespace ensil::prep

#include "preprocessing/isosurface_pipeline.h"

#include <tbb/parallel_for.h>

#include <chrono>

#include "preprocessing/decimation.h"
#include "preprocessing/marching_cubes.h"
#include "preprocessing/vertex_attributes.h"

namespace ensil::prep {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Runs work(i) for i in [0, n) in parallel; reports progress between lo and hi of the whole.
template <typename Work>
void forEachField(std::size_t n, const std::stop_token& stop, const data::Progress& progress,
                  double lo, double hi, Work&& work) {
    data::PartsProgress fieldsDone(progress, n, lo, hi);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        if (stop.stop_requested()) return;
        work(i);
        fieldsDone.partDone();
    });
    data::throwIfStopped(stop);
}

}  // namespace

MeshedField meshField(const data::Grid& grid, const data::FieldValues& field, float isovalue,
                      const AxisTables& axes, const EnsembleMoments* moments,
                      const PipelineOptions& options, const std::stop_token& stop) {
    MeshedField out;
    FieldMeshStats& s = out.stats;
    auto t = Clock::now();
    data::TriangleMesh mesh = extractIsosurface(grid, field, isovalue, stop);
    s.seconds.meshes = since(t);
    s.extracted = mesh.triangleCount();
    t = Clock::now();
    DecimationResult d =
        decimateMesh(std::move(mesh), options.decimate ? options.maxErrorCells : 0.0F);
    mesh = std::move(d.mesh);
    s.error = d.errorCells;
    s.seconds.decimation = since(t);
    t = Clock::now();
    const VertexAttributes a =
        computeVertexAttributes(grid, field, mesh, axes, isovalue, moments, stop);
    out.mesh = packMesh(mesh, a);
    s.seconds.attributes = since(t);
    s.triangles = mesh.triangleCount();
    s.vertices = mesh.vertexCount();
    return out;
}

void summariseMeshes(IsovalueMeshes& meshes, const std::vector<FieldMeshStats>& stats,
                     double wallSeconds) {
    StageSeconds busy;
    for (const FieldMeshStats& s : stats) {
        busy.meshes += s.seconds.meshes;
        busy.decimation += s.seconds.decimation;
        busy.attributes += s.seconds.attributes;
        meshes.trianglesExtracted += s.extracted;
        meshes.triangles += s.triangles;
        meshes.vertices += s.vertices;
        meshes.worstErrorCells = std::max(meshes.worstErrorCells, s.error);
    }
    const double total = busy.meshes + busy.decimation + busy.attributes;
    if (total > 0.0) {
        meshes.seconds = {wallSeconds * busy.meshes / total, wallSeconds * busy.decimation / total,
                          wallSeconds * busy.attributes / total};
    }
}

IsovalueMeshes buildIsovalueMeshes(const data::Ensemble& ensemble, const EnsembleMoments& moments,
                                   const data::DisplayFrame& frame, const PipelineOptions& options,
                                   const std::stop_token& stop, const data::Progress& progress) {
    const std::size_t n = ensemble.memberCount();
    // Field n is the mean member.
    const auto field = [&](std::size_t i) -> const data::FieldValues& {
        return i < n ? ensemble.members[i].values : moments.mean.values;
    };
    const float iso = options.isovalue;
    const AxisTables axes = axisTables(frame);
    IsovalueMeshes out;
    out.isovalue = iso;
    out.members.resize(n);

    // One task per member runs every stage, so each full-resolution mesh is freed as soon as
    // it is packed: peak memory holds a few raw meshes, not all of them.
    std::vector<FieldMeshStats> stats(n + 1);
    const auto start = Clock::now();
    forEachField(n + 1, stop, progress, 0.0, 1.0, [&](std::size_t i) {
        // The mean has no outlyingness of its own: it is drawn solid, never removed.
        MeshedField m = meshField(ensemble.grid, field(i), iso, axes, i < n ? &moments : nullptr,
                                  options, stop);
        (i < n ? out.members[i] : out.mean) = std::move(m.mesh);
        stats[i] = m.stats;
    });
    const double wall = since(start);

    summariseMeshes(out, stats, wall);
    return out;
}

}  // namespace ensil::prep

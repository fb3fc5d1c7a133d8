#include "preprocessing/isosurface_pipeline.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <mutex>

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
void forEachField(std::size_t n, const std::stop_token& stop, const Progress& progress, double lo,
                  double hi, Work&& work) {
    std::atomic<std::size_t> done{0};
    std::mutex reportMutex;
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        if (stop.stop_requested()) return;
        work(i);
        const std::size_t finished = ++done;
        const std::lock_guard lock(reportMutex);  // keeps reports monotonic
        report(progress, lo + (hi - lo) * static_cast<double>(finished) / static_cast<double>(n));
    });
    throwIfStopped(stop);
}

}  // namespace

std::size_t IsovalueMeshes::gpuBytes() const {
    std::size_t bytes = mean.gpuBytes();
    for (const PackedMesh& m : members) bytes += m.gpuBytes();
    return bytes;
}

IsovalueMeshes buildIsovalueMeshes(const data::Ensemble& ensemble, const EnsembleMoments& moments,
                                   const data::DisplayFrame& frame, const PipelineOptions& options,
                                   const std::stop_token& stop, const Progress& progress) {
    const std::size_t n = ensemble.memberCount();
    // Field n is the mean member.
    const auto field = [&](std::size_t i) -> const data::FieldValues& {
        return i < n ? ensemble.members[i].values : moments.mean.values;
    };
    const float iso = options.isovalue;
    IsovalueMeshes out;
    out.isovalue = iso;
    std::vector<data::TriangleMesh> meshes(n + 1);

    auto start = Clock::now();
    forEachField(n + 1, stop, progress, 0.0, 0.4, [&](std::size_t i) {
        meshes[i] = extractIsosurface(ensemble.grid, field(i), iso, stop);
    });
    out.seconds.meshes = since(start);
    for (const auto& m : meshes) out.trianglesExtracted += m.triangleCount();

    start = Clock::now();
    std::vector<float> errors(n + 1, 0.0F);
    forEachField(n + 1, stop, progress, 0.4, 0.6, [&](std::size_t i) {
        DecimationResult d =
            decimateMesh(meshes[i], options.decimate ? options.maxErrorCells : 0.0F);
        meshes[i] = std::move(d.mesh);
        errors[i] = d.errorCells;
    });
    out.seconds.decimation = since(start);

    start = Clock::now();
    const AxisTables axes = axisTables(frame);
    out.members.resize(n);
    forEachField(n + 1, stop, progress, 0.6, 1.0, [&](std::size_t i) {
        // The mean has no outlyingness of its own: it is drawn solid, never removed.
        const VertexAttributes a = computeVertexAttributes(ensemble.grid, field(i), meshes[i], axes,
                                                           iso, i < n ? &moments : nullptr, stop);
        (i < n ? out.members[i] : out.mean) = packMesh(meshes[i], a);
    });
    out.seconds.attributes = since(start);

    for (std::size_t i = 0; i <= n; ++i) {
        out.triangles += meshes[i].triangleCount();
        out.vertices += meshes[i].vertexCount();
        out.worstErrorCells = std::max(out.worstErrorCells, errors[i]);
    }
    return out;
}

}  // namespace ensil::prep

#include "preprocessing/preview_meshes.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "preprocessing/decimation.h"
#include "preprocessing/marching_cubes.h"
#include "preprocessing/mesh_packing.h"
#include "preprocessing/vertex_attributes.h"

namespace ensil::prep {
namespace {

// Axes this short are kept whole: sampling them would lose whole levels of a weather field,
// and they add little work.
constexpr std::size_t kShortAxis = 32;

std::vector<std::uint32_t> sampledIndices(std::size_t n, std::size_t stride) {
    std::vector<std::uint32_t> indices;
    for (std::size_t i = 0; i + 1 < n; i += stride)
        indices.push_back(static_cast<std::uint32_t>(i));
    indices.push_back(static_cast<std::uint32_t>(n - 1));
    return indices;
}

data::Axis indexAxis(const std::vector<std::uint32_t>& indices) {
    data::Axis axis;
    axis.values.assign(indices.begin(), indices.end());
    return axis;
}

// A coarse coordinate c + t (c a sampled point's rank) back in the full grid's index space:
// linear between the two sampled grid indices, as marching cubes interpolated between them.
float fullIndex(const std::vector<std::uint32_t>& indices, float coarse) {
    const auto last = indices.size() - 1;
    const auto c = std::min(static_cast<std::size_t>(std::max(coarse, 0.0F)), last);
    if (c == last) return static_cast<float>(indices[last]);
    const float t = coarse - static_cast<float>(c);
    return static_cast<float>(indices[c]) + t * static_cast<float>(indices[c + 1] - indices[c]);
}

}  // namespace

PreviewSampling previewSampling(const data::Grid& grid, std::size_t pointBudget) {
    const std::array<std::size_t, 3> n{grid.nx(), grid.ny(), grid.nz()};
    const std::size_t longest = std::max({n[0], n[1], n[2]});
    PreviewSampling s;
    for (std::size_t stride = 1;; ++stride) {
        for (std::size_t a = 0; a < 3; ++a) {
            s.indices[a] = sampledIndices(n[a], n[a] <= kShortAxis ? 1 : stride);
        }
        s.stride = static_cast<int>(stride);
        if (s.pointCount() <= pointBudget || stride >= longest) return s;
    }
}

IsovalueMeshes buildPreviewMeshes(const data::Ensemble& ensemble, const EnsembleMoments& moments,
                                  const data::DisplayFrame& frame, float isovalue,
                                  const PreviewOptions& options, const std::stop_token& stop) {
    const std::size_t n = ensemble.memberCount();
    const data::Grid& grid = ensemble.grid;
    const PreviewSampling sampling = previewSampling(grid, options.pointBudget);
    const auto& [ix, iy, iz] = sampling.indices;
    const data::Grid coarse(indexAxis(ix), indexAxis(iy), indexAxis(iz));
    const AxisTables axes = axisTables(frame);

    IsovalueMeshes out;
    out.isovalue = isovalue;
    out.members.resize(n);
    std::vector<FieldMeshStats> stats(n + 1);
    tbb::parallel_for(std::size_t{0}, n + 1, [&](std::size_t m) {
        if (stop.stop_requested()) return;
        const data::FieldValues& field = m < n ? ensemble.members[m].values : moments.mean.values;
        std::vector<float> sampled;
        sampled.reserve(sampling.pointCount());
        for (const std::uint32_t k : iz) {
            for (const std::uint32_t j : iy) {
                for (const std::uint32_t i : ix) sampled.push_back(field[grid.index(i, j, k)]);
            }
        }
        data::TriangleMesh mesh = extractIsosurface(coarse, sampled, isovalue, stop);
        for (glm::vec3& p : mesh.positions) {
            p = {fullIndex(ix, p.x), fullIndex(iy, p.y), fullIndex(iz, p.z)};
        }
        stats[m].extracted = mesh.triangleCount();
        DecimationResult d = decimateMesh(std::move(mesh), options.maxErrorCells);
        stats[m].error = d.errorCells;
        const VertexAttributes a = computeVertexAttributes(grid, field, d.mesh, axes, isovalue,
                                                           m < n ? &moments : nullptr, stop);
        stats[m].triangles = d.mesh.triangleCount();
        stats[m].vertices = d.mesh.vertexCount();
        (m < n ? out.members[m] : out.mean) = packMesh(d.mesh, a);
    });
    data::throwIfStopped(stop);
    summariseMeshes(out, stats, 0.0);  // totals; a preview's stages are not timed
    return out;
}

}  // namespace ensil::prep

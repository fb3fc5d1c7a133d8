#include "preprocessing/context_surfaces.h"

#include <tbb/parallel_invoke.h>

#include "preprocessing/column_maximum.h"
#include "preprocessing/ensemble_statistics.h"

namespace ensil::prep {

ContextSurfaces buildContextSurfaces(const data::Ensemble& ensemble,
                                     const data::DisplayFrame& frame,
                                     const PipelineOptions& options, const std::stop_token& stop,
                                     const data::Progress& progress) {
    ContextSurfaces out;
    EnsembleStatistics statistics = computeEnsembleStatistics(
        ensemble, options.isovalue, stop, [&](double f) { data::report(progress, 0.4 * f); });
    out.boxplot = computeContourBoxplot(ensemble, options.isovalue, stop,
                                        [&](double f) { data::report(progress, 0.4 + 0.3 * f); });
    // Each of the three fields runs from 0 to 1 (a share of members, or inside / outside), so
    // its surface is at one half whatever the variable's isovalue.
    constexpr float kHalf = 0.5F;
    const AxisTables axes = axisTables(frame);
    const auto mesh = [&](const data::FieldValues& field, data::PackedMesh& into) {
        into = meshField(ensemble.grid, field, kHalf, axes, nullptr, options, stop).mesh;
    };
    tbb::parallel_invoke([&] { mesh(statistics.exceedance, out.probability); },
                         [&] { mesh(out.boxplot.bandInner, out.bandInner); },
                         [&] { mesh(out.boxplot.bandOuter, out.bandOuter); });
    data::throwIfStopped(stop);
    out.exceedanceColumnMaximum =
        computeColumnMaximum(ensemble.grid, {"exceedance", statistics.exceedance});
    out.exceedance = std::move(statistics.exceedance);
    data::report(progress, 1.0);
    return out;
}

void addContextSurfaces(data::MeshSet& meshes, const ContextSurfaces& context) {
    meshes.probability = context.probability;
    meshes.bandInner = context.bandInner;
    meshes.bandOuter = context.bandOuter;
    meshes.median = static_cast<int>(context.boxplot.median);
    meshes.outliers.assign(context.boxplot.outliers.begin(), context.boxplot.outliers.end());
}

}  // namespace ensil::prep

#include "preprocessing/context_surfaces.h"

#include "preprocessing/band_envelope.h"
#include "preprocessing/column_maximum.h"
#include "preprocessing/exceedance.h"
#include "preprocessing/member_median.h"
#include "preprocessing/side_by_side.h"

namespace ensil::prep {

ContextSurfaces buildContextSurfaces(const data::Ensemble& ensemble,
                                     const data::DisplayFrame& frame,
                                     const PipelineOptions& options, const std::stop_token& stop,
                                     const data::Progress& progress, ContextParts parts) {
    ContextSurfaces out;
    // The exceedance and the boxplot read only the ensemble: side by side (the boxplot's loops
    // are serial), each as it would be alone.
    data::FieldValues exceedance;
    data::PartsProgress partsDone(progress, 2, 0.0, 0.7);
    runSideBySide(
        [&] {
            exceedance = computeExceedance(ensemble, options.isovalue, stop);
            partsDone.partDone();
        },
        [&] {
            out.boxplot = computeContourBoxplot(ensemble, options.isovalue, stop);
            partsDone.partDone();
        });
    data::throwIfStopped(stop);
    out.exceedanceColumnMaximum = computeColumnMaximum(ensemble.grid, {"exceedance", exceedance});
    if (parts == ContextParts::FiguresAndSurfaces) {
        // Each is the isovalue's surface of a field that separates the same grid points as
        // its definition and is interpolated as the members are: where half the members
        // exceed c, of their median (member_median.h); the band's, of its members' lowest and
        // highest values (band_envelope.h).
        const data::FieldValues median = computeMemberMedian(ensemble, stop);
        const BandEnvelope band = computeBandEnvelope(ensemble, out.boxplot.bandMembers, stop);
        const AxisTables axes = axisTables(frame);
        const auto mesh = [&](const data::FieldValues& field, float level, data::PackedMesh& into) {
            into = meshField(ensemble.grid, field, level, axes, nullptr, options, stop).mesh;
        };
        runSideBySide([&] { mesh(median, options.isovalue, out.probability); },
                      [&] { mesh(band.lowest, options.isovalue, out.bandInner); },
                      [&] { mesh(band.highest, options.isovalue, out.bandOuter); });
        data::throwIfStopped(stop);
    }
    out.exceedance = std::move(exceedance);
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

#include "engine/isovalue_job.h"

// oneTBB before Qt: Qt defines `emit` as a macro, and oneTBB declares functions of that name
// (preprocessing/side_by_side.h includes this too, after Qt).
#include <tbb/parallel_invoke.h>

#include <QStandardPaths>
#include <chrono>

#include "data/error.h"
#include "preprocessing/member_summaries.h"
#include "preprocessing/mesh_cache.h"
#include "preprocessing/side_by_side.h"

namespace ensil::engine {
namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// addContextOf's second half: the hand-over of buildContextOf's surfaces into `out` (with
// its seconds).
void addContext(IsovalueOutcome& out, prep::ContextSurfaces context, double seconds) {
    prep::addContextSurfaces(out.meshes, context);
    out.boxplot = std::move(context.boxplot);
    out.exceedanceColumnMaximum = std::move(context.exceedanceColumnMaximum);
    out.exceedance = std::make_shared<const data::FieldValues>(std::move(context.exceedance));
    out.seconds["context_surfaces"] = seconds;
}
}  // namespace

prep::ContextSurfaces buildContextOf(const IsovalueJobInput& in, const std::stop_token& stop,
                                     const data::Progress& progress) {
    return prep::buildContextSurfaces(
        *in.ensemble, data::DisplayFrame(in.ensemble->grid, in.verticalExaggeration), in.options,
        stop, progress, in.context);
}

std::string defaultMeshCacheDirectory() {
    return (QStandardPaths::writableLocation(QStandardPaths::CacheLocation) +
            QStringLiteral("/meshes"))
        .toStdString();
}

void addContextOf(const IsovalueJobInput& in, IsovalueOutcome& out, double from, double to,
                  const std::stop_token& stop, const data::Progress& progress) {
    const auto start = Clock::now();
    prep::ContextSurfaces context =
        buildContextOf(in, stop, [&](double f) { data::report(progress, from + (to - from) * f); });
    addContext(out, std::move(context), since(start));
}

IsovalueOutcome runIsovalueJob(const IsovalueJobInput& in, const std::stop_token& stop,
                               const data::Progress& progress) {
    IsovalueOutcome out;
    const std::string key =
        in.sourceKey + "; " + prep::pipelineKey(in.options, in.verticalExaggeration);
    std::optional<prep::MeshCache> cache;
    if (in.cacheDirectory) cache.emplace(*in.cacheDirectory);
    // The members' meshes (or the cache's), the context surfaces, and the distances (between
    // members and from each to the mean member, in one pass) read only the ensemble and write
    // results of their own: all run side by side, so that the serial parts of each (the
    // context's largest surface, the last members' meshes, the distances' merge) leave no core
    // idle. Each result is what it is when run alone; their seconds overlap. The distances to
    // the mean are cheap beside the meshes and depend on nothing the cache keeps: made afresh,
    // so the cache's format stays as it is. The meshes are most of the work: three quarters of
    // the progress.
    data::WeightedPartsProgress parts(progress, {0.75, 0.125, 0.125});
    std::optional<prep::IsovalueMeshes> meshes;
    std::map<std::string, double> meshSeconds;
    prep::ContextSurfaces context;
    double contextSeconds = 0.0, similaritySeconds = 0.0;
    const auto& mean = in.moments->mean.values;
    prep::runSideBySide(
        [&] {
            const auto start = Clock::now();
            if (cache) meshes = cache->load(key);
            if (meshes) {
                out.fromCache = true;
                meshSeconds["cache_read"] = since(start);
            } else {
                meshes = prep::buildIsovalueMeshes(
                    *in.ensemble, *in.moments,
                    data::DisplayFrame(in.ensemble->grid, in.verticalExaggeration), in.options,
                    stop, parts.part(0));
                meshSeconds["meshes"] = meshes->seconds.meshes;
                meshSeconds["decimation"] = meshes->seconds.decimation;
                meshSeconds["attributes"] = meshes->seconds.attributes;
                if (cache) {
                    try {
                        cache->store(key, *meshes);
                    } catch (const data::Error& e) {
                        // A cache that cannot be written only costs time next time: said, not
                        // fatal.
                        out.cacheWarning = e.what();
                    }
                }
            }
            parts.part(0)(1.0);
        },
        [&] {
            const auto t = Clock::now();
            context = buildContextOf(in, stop, {});
            contextSeconds = since(t);
            parts.part(1)(1.0);
        },
        [&] {
            const auto t = Clock::now();
            prep::DistancesAndReference distances = prep::computeDistancesAndReference(
                *in.ensemble, {mean.data(), mean.size()}, in.options.isovalue, stop);
            out.distances = std::move(distances.matrix);
            out.distancesToMean = std::move(distances.toReference);
            similaritySeconds = since(t);
            parts.part(2)(1.0);
        });
    data::throwIfStopped(stop);
    out.meshes = std::move(*meshes);
    out.seconds = std::move(meshSeconds);
    addContext(out, std::move(context), contextSeconds);
    out.seconds["similarity"] = similaritySeconds;
    auto start = Clock::now();
    out.tree = prep::clusterMembers(out.distances, in.linkage, stop);
    out.seconds["clustering"] = since(start);
    start = Clock::now();
    out.meanOutlyingness.reserve(out.meshes.members.size());
    for (const data::PackedMesh& mesh : out.meshes.members) {
        out.meanOutlyingness.push_back(prep::meanOutlyingness(mesh));
    }
    out.seconds["member_summaries"] = since(start);
    return out;
}

}  // namespace ensil::engine

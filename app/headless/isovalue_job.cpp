#include "app/headless/isovalue_job.h"

// oneTBB before Qt: Qt defines `emit` as a macro, and oneTBB declares functions of that name.
#include <tbb/parallel_invoke.h>

#include <QStandardPaths>
#include <chrono>

#include "data/error.h"
#include "preprocessing/context_surfaces.h"
#include "preprocessing/member_summaries.h"
#include "preprocessing/mesh_cache.h"

namespace ensil::app {
namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}
}  // namespace

std::string defaultMeshCacheDirectory() {
    return (QStandardPaths::writableLocation(QStandardPaths::CacheLocation) +
            QStringLiteral("/meshes"))
        .toStdString();
}

void addContextOf(const IsovalueJobInput& in, IsovalueOutcome& out, double from, double to,
                  const std::stop_token& stop, const data::Progress& progress) {
    const auto start = Clock::now();
    prep::ContextSurfaces context = prep::buildContextSurfaces(
        *in.ensemble, data::DisplayFrame(in.ensemble->grid, in.verticalExaggeration), in.options,
        stop, [&](double f) { data::report(progress, from + (to - from) * f); });
    prep::addContextSurfaces(out.meshes, context);
    out.boxplot = std::move(context.boxplot);
    out.exceedanceColumnMaximum = std::move(context.exceedanceColumnMaximum);
    out.exceedance = std::make_shared<const data::FieldValues>(std::move(context.exceedance));
    out.seconds["context_surfaces"] = since(start);
}

IsovalueOutcome runIsovalueJob(const IsovalueJobInput& in, const std::stop_token& stop,
                               const data::Progress& progress) {
    IsovalueOutcome out;
    const std::string key =
        in.sourceKey + "; " + prep::pipelineKey(in.options, in.verticalExaggeration);
    std::optional<prep::MeshCache> cache;
    if (in.cacheDirectory) cache.emplace(*in.cacheDirectory);
    auto start = Clock::now();
    std::optional<prep::IsovalueMeshes> cached;
    if (cache) cached = cache->load(key);
    if (cached) {
        out.meshes = std::move(*cached);
        out.fromCache = true;
        out.seconds["cache_read"] = since(start);
    } else {
        out.meshes = prep::buildIsovalueMeshes(
            *in.ensemble, *in.moments,
            data::DisplayFrame(in.ensemble->grid, in.verticalExaggeration), in.options, stop,
            [&](double f) { data::report(progress, 0.75 * f); });
        out.seconds["meshes"] = out.meshes.seconds.meshes;
        out.seconds["decimation"] = out.meshes.seconds.decimation;
        out.seconds["attributes"] = out.meshes.seconds.attributes;
        if (cache) {
            try {
                cache->store(key, out.meshes);
            } catch (const data::Error& e) {
                // A cache that cannot be written only costs time next time: said, not fatal.
                out.cacheWarning = e.what();
            }
        }
    }
    // The context surfaces, the distances and each member's distance to the mean read only the
    // ensemble and write parts of their own: run side by side (each is parallel inside, but
    // partly serial), so the cores stay busy. Each result is what it is when run alone; their
    // seconds overlap. The summaries are cheap beside the meshes and depend on nothing the
    // cache keeps: made afresh, so the cache's format stays as it is.
    // Only the context's part writes out.seconds while they run.
    data::PartsProgress partsDone(progress, 3, 0.75, 1.0);
    const auto& mean = in.moments->mean.values;
    double similaritySeconds = 0.0, toMeanSeconds = 0.0;
    tbb::parallel_invoke(
        [&] {
            addContextOf(in, out, 0.0, 0.0, stop, {});
            partsDone.partDone();
        },
        [&] {
            const auto t = Clock::now();
            out.distances = prep::computeDistanceMatrix(*in.ensemble, in.options.isovalue, stop);
            similaritySeconds = since(t);
            partsDone.partDone();
        },
        [&] {
            const auto t = Clock::now();
            out.distancesToMean = prep::distancesToField(*in.ensemble, {mean.data(), mean.size()},
                                                         in.options.isovalue, stop);
            toMeanSeconds = since(t);
            partsDone.partDone();
        });
    data::throwIfStopped(stop);
    out.seconds["similarity"] = similaritySeconds;
    out.seconds["member_summaries"] = toMeanSeconds;
    start = Clock::now();
    out.tree = prep::clusterMembers(out.distances, in.linkage, stop);
    out.seconds["clustering"] = since(start);
    start = Clock::now();
    out.meanOutlyingness.reserve(out.meshes.members.size());
    for (const data::PackedMesh& mesh : out.meshes.members) {
        out.meanOutlyingness.push_back(prep::meanOutlyingness(mesh));
    }
    out.seconds["member_summaries"] += since(start);
    return out;
}

}  // namespace ensil::app

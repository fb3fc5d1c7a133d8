#include "engine/streamed_isovalue_job.h"

#include <chrono>
#include <optional>

#include "data/error.h"
#include "data/reader_support.h"
#include "engine/streaming_run.h"
#include "preprocessing/member_summaries.h"
#include "preprocessing/mesh_cache.h"
#include "preprocessing/streaming_preprocess.h"

namespace ensil::engine {
namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// The copy's members by name, as the streamed run names them.
std::vector<std::string> memberNamesOf(const data::Ensemble& ensemble) {
    std::vector<std::string> names;
    for (const data::Member& member : ensemble.members) names.push_back(member.name);
    return names;
}
}  // namespace

IsovalueOutcome runStreamedIsovalueJob(const IsovalueJobInput& in, const StreamedSource& source,
                                       const std::stop_token& stop,
                                       const data::Progress& progress) {
    IsovalueOutcome out;
    const data::EnsembleDescription& d = source.description;
    const std::string key =
        in.sourceKey + "; " + prep::pipelineKey(in.options, in.verticalExaggeration);
    std::optional<prep::MeshCache> cache;
    if (in.cacheDirectory) cache.emplace(*in.cacheDirectory);
    std::optional<prep::IsovalueMeshes> cached;
    if (cache) cached = cache->load(key);
    auto start = Clock::now();
    const prep::StreamingPlan& plan = source.plan;
    std::vector<std::string> names;
    if (cached) {
        // The meshes are known; the distances still need the whole data: the slab pass, and
        // each member read once more for its distance to the mean (no meshing).
        const prep::SlabSums sums =
            prep::sumSlabs(source.selection, d, plan.slabs, in.options.isovalue, stop,
                           [&](double f) { data::report(progress, 0.5 * f); });
        prep::StreamedEnsemble concluded;
        const std::vector<std::size_t> keep =
            prep::concludeSlabs(sums, source.selection, d, {}, concluded);
        out.distancesToMean = prep::distancesToMeanOf(
            source.selection, d, keep, sums.moments, in.options.isovalue, plan.membersAtOnce, stop,
            [&](double f) { data::report(progress, 0.5 + 0.35 * f); });
        out.meshes = std::move(*cached);
        out.fromCache = true;
        out.distances = std::move(concluded.distances);
        names = std::move(concluded.memberNames);
        out.seconds["slabs"] = since(start);
    } else {
        // No range check: the isovalue comes from the copy's range, within the whole data's.
        prep::StreamedEnsemble streamed =
            prep::streamPreprocess(source.selection, d, plan, in.options, in.verticalExaggeration,
                                   {}, stop, [&](double f) { data::report(progress, 0.85 * f); });
        recordStreamedSeconds(out.seconds, streamed);
        out.meshes = std::move(streamed.meshes);
        out.distances = std::move(streamed.distances);
        out.distancesToMean = std::move(streamed.distancesToMean);
        names = std::move(streamed.memberNames);
        if (cache) {
            try {
                cache->store(key, out.meshes);
            } catch (const data::Error& e) {
                out.cacheWarning = e.what();
            }
        }
    }
    out.seconds["streaming"] = since(start);
    if (names != memberNamesOf(*in.ensemble)) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "the members with data in " + data::sourceOf(source.selection.paths) +
                              " (" + data::quotedList(names) +
                              ") are not those of its copy in memory (" +
                              data::quotedList(memberNamesOf(*in.ensemble)) +
                              "): a member has values only between the copy's points; open "
                              "the data with a larger memory budget");
    }
    // The meshes of the members stay as the whole data gave them; the context surfaces are
    // the copy's, on its coarser grid in the same box.
    addContextOf(in, out, 0.85, 0.95, stop, progress);
    start = Clock::now();
    out.tree = prep::clusterMembers(out.distances, in.linkage, stop);
    out.seconds["clustering"] = since(start);
    for (const data::PackedMesh& mesh : out.meshes.members) {
        out.meanOutlyingness.push_back(prep::meanOutlyingness(mesh));
    }
    data::report(progress, 1.0);
    return out;
}

}  // namespace ensil::engine
